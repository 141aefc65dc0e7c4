// Shared by the studio's browser test and its gallery script: a studio server on a free port, and
// Debian's chromium, headless with software WebGL, driven by playwright-core from web/node_modules.
import {spawn} from 'node:child_process';
import {createInterface} from 'node:readline';
import path from 'node:path';
import {fileURLToPath} from 'node:url';

export const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

// `texsynth studio ARGS --port 0 --json`; its first line of output says the address.
export async function startStudio(binary, args) {
  const server = spawn(binary, ['studio', ...args, '--port', '0', '--json'], {stdio: ['ignore', 'pipe', 'inherit']});
  const line = await new Promise((resolve, reject) => {
    createInterface({input: server.stdout}).once('line', resolve);
    server.once('exit', (code) => reject(new Error(`texsynth studio exited with ${code}`)));
  });
  return {server, url: JSON.parse(line).url.replace(/\/$/, '')};
}

// Software WebGL (SwiftShader), and no background traffic on a closed network.
export async function launchChromium() {
  let chromium;
  try {
    ({chromium} = await import(path.join(root, 'web/node_modules/playwright-core/index.mjs')));
  } catch (error) {
    throw new Error('playwright-core is missing: run scripts/install-deps.sh (npm ci in web/)');
  }
  return chromium.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-background-networking',
           '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic'],
  });
}
