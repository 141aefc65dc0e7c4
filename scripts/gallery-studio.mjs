// Screenshots of texsynth studio for the gallery: the bunny's sketch with the field's glyphs, the
// lazy solid following it, and the model cut open. Run by scripts/gallery-studio.sh.
// Usage: node scripts/gallery-studio.mjs TEXSYNTH_BINARY WORK_DIR
import {readFileSync} from 'node:fs';
import path from 'node:path';

import {launchChromium, root, startStudio} from '../tests/web/studio_harness.mjs';

const [binary, work] = process.argv.slice(2);
const {server, url} = await startStudio(binary, ['bunny00', 'Stone/pink_marble']);
await fetch(url + '/api/sketch', {method: 'PUT', body: readFileSync(path.join(root, 'examples/sketches/bunny.json'))});

const browser = await launchChromium();
try {
  const page = await browser.newPage({viewport: {width: 1280, height: 820}});
  await page.goto(url + '/');
  await page.waitForFunction(() => window.studio?.ready, null, {timeout: 60000});
  const shot = async (name) => {
    await page.waitForTimeout(500);
    await page.screenshot({path: path.join(work, name)});
  };
  await shot('studio_sketch.png');
  await page.uncheck('#glyph-toggle');
  await page.selectOption('#method-select', 'lazy');
  await page.click('#preview-button');
  await page.waitForFunction(() => window.studio.lastResult?.kind === 'preview' && window.studio.lastResult.stage === 'final',
                             null, {timeout: 300000});
  await shot('studio_lazy.png');
  await page.check('#cut-toggle');
  await page.selectOption('#cut-axis', 'x');
  await page.waitForFunction(() => window.studio.cuts >= 1 && window.studio.lastResult.axis === 'x', null,
                             {timeout: 300000});
  await shot('studio_cut.png');
} finally {
  await browser.close();
  server.kill('SIGTERM');
}
