// The studio as a person uses it, in Debian's chromium driven by playwright-core: load the page,
// draw a stroke on the bunny, pick an exemplar, cut the model open and move the cut, export a .glb
// and load it back. Screenshots of each step go to OUTPUT_DIR.
// Usage: node tests/web/studio_browser.mjs TEXSYNTH_BINARY OUTPUT_DIR
import {mkdirSync, readFileSync} from 'node:fs';
import path from 'node:path';

import {launchChromium, startStudio} from './studio_harness.mjs';

const [binary, outputDir] = process.argv.slice(2);
if (!binary || !outputDir) {
  console.error('usage: node studio_browser.mjs TEXSYNTH_BINARY OUTPUT_DIR');
  process.exit(2);
}
mkdirSync(outputDir, {recursive: true});

function fail(message) {
  throw new Error(message);
}
function check(condition, message) {
  if (!condition) fail(message);
  console.log(`ok: ${message}`);
}

const {server, url} = await startStudio(binary, ['bunny00', 'Stone/pink_marble']);
const api = async (method, route, body) => {
  const response = await fetch(url + route, {method, body});
  const text = await response.text();
  return {status: response.status, json: () => JSON.parse(text), text};
};

const browser = await launchChromium();
let exitCode = 0;
try {
  const page = await browser.newPage({viewport: {width: 1200, height: 800}, acceptDownloads: true});
  const pageErrors = [];
  page.on('pageerror', (error) => pageErrors.push(error.message));
  const shot = (name) => page.screenshot({path: path.join(outputDir, name)});
  // The 3D view's pixels, kept in the page under `name`; difference() compares two of them.
  const capture = (name) => page.evaluate((name) => {
    const canvas = document.querySelector('#view canvas');
    const copy = Object.assign(document.createElement('canvas'), {width: canvas.width, height: canvas.height});
    const context = copy.getContext('2d');
    context.drawImage(canvas, 0, 0);
    (window.captures ||= {})[name] = context.getImageData(0, 0, copy.width, copy.height).data;
  }, name);
  // The fraction of pixels whose colour changed by more than 24 levels in some channel.
  const difference = (a, b) => page.evaluate(([a, b]) => {
    const x = window.captures[a], y = window.captures[b];
    let changed = 0;
    for (let i = 0; i < x.length; i += 4)
      if (Math.max(Math.abs(x[i] - y[i]), Math.abs(x[i + 1] - y[i + 1]), Math.abs(x[i + 2] - y[i + 2])) > 24) ++changed;
    return changed / (x.length / 4);
  }, [a, b]);
  const settle = () => page.waitForTimeout(400);  // a frame or two after a state change

  // 1. The page loads with the bunny and the identity field's glyphs.
  await page.goto(url + '/');
  await page.waitForFunction(() => window.studio?.ready, null, {timeout: 60000});
  await settle();
  await shot('01_loaded.png');
  await capture('loaded');
  const glyphsBefore = (await api('GET', '/api/field/glyphs?across=16')).json();
  check(glyphsBefore.glyphs.length > 50, `the page shows the bunny with ${glyphsBefore.glyphs.length} field glyphs`);

  // 2. A stroke drawn with the mouse across the bunny's body becomes a curve on its surface.
  await page.check('#draw-toggle');
  const box = await page.locator('#view canvas').boundingBox();
  const y = box.y + box.height * 0.6, x0 = box.x + box.width * 0.42, x1 = box.x + box.width * 0.62;
  await page.mouse.move(x0, y);
  await page.mouse.down();
  for (let i = 1; i <= 24; ++i) await page.mouse.move(x0 + ((x1 - x0) * i) / 24, y - 30 * Math.sin((Math.PI * i) / 24));
  await page.mouse.up();
  await page.waitForFunction(() => window.studio.curveCount === 1, null, {timeout: 20000});
  await page.uncheck('#draw-toggle');
  const scene = (await api('GET', '/api/scene')).json();
  check(scene.curves.length === 1, 'the server received one curve');
  const sketch = (await api('GET', '/api/sketch')).json();
  const drawn = sketch.curves[0].points;
  const glyphsAfter = (await api('GET', '/api/field/glyphs?across=16')).json();
  const placed = glyphsAfter.curves[0].samples;
  const diagonal = Math.hypot(...scene.mesh.bounds[1].map((v, i) => v - scene.mesh.bounds[0][i]));
  // Every drawn point lies on the surface: the server snapped it to its closest surface point (its
  // samples) and those are no farther than a hundredth of the model's size.
  const nearest = (p) => Math.min(...placed.map((q) => Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2])));
  const worst = Math.max(...drawn.map(nearest));
  check(drawn.length >= 5 && worst < 0.01 * diagonal,
        `the curve's ${drawn.length} points lie on the surface (farthest ${(worst / diagonal).toFixed(4)} of the diagonal from the placed samples)`);
  let turned = 0;
  for (let i = 0; i < glyphsAfter.glyphs.length; ++i) {
    const a = glyphsBefore.glyphs[i].x, b = glyphsAfter.glyphs[i].x;
    if (a[0] * b[0] + a[1] * b[1] + a[2] * b[2] < 0.999) ++turned;
  }
  check(glyphsAfter.revision === 1 && turned > glyphsAfter.glyphs.length / 10,
        `the glyphs changed: ${turned} of ${glyphsAfter.glyphs.length} turned`);
  await settle();
  await shot('02_stroke_and_glyphs.png');

  // 3. Choosing an exemplar shows the textured preview.
  await page.uncheck('#glyph-toggle');
  await settle();
  await capture('untextured');
  await page.selectOption('#exemplar-select', {label: 'Wood/walnut'});
  await page.waitForFunction(() => window.studio.previews >= 1, null, {timeout: 30000});
  await settle();
  await shot('03_textured.png');
  await capture('textured');
  const textured = await difference('untextured', 'textured');
  check(textured > 0.05, `the textured preview differs from the untextured model (${(100 * textured).toFixed(1)}% of pixels)`);

  // 4. The cut opens the model; moving it updates the interior view.
  await page.check('#cut-toggle');
  await page.waitForFunction(() => window.studio.cuts >= 1, null, {timeout: 60000});
  await settle();
  await shot('04_cut.png');
  await capture('cut');
  await page.locator('#cut-position').fill('0.3');
  await page.waitForFunction(() => window.studio.cuts >= 2 && window.studio.lastResult.position < 0.35, null,
                             {timeout: 60000});
  await settle();
  await shot('05_cut_moved.png');
  await capture('moved');
  const moved = await difference('cut', 'moved');
  check(moved > 0.02, `moving the cut updated the interior view (${(100 * moved).toFixed(1)}% of pixels)`);

  // 5. Export the textured mesh and load it back through texsynth's own loader.
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('[data-export="glb"]')]);
  const file = path.join(outputDir, 'exported.glb');
  await download.saveAs(file);
  const bytes = readFileSync(file);
  check(bytes.subarray(0, 4).toString() === 'glTF', `the export is a binary glTF (${bytes.length} bytes)`);
  const back = await api('POST', '/api/uploads/mesh?format=glb&name=exported', bytes);
  check(back.status === 201, `the exported .glb loads back (${back.text})`);

  check(pageErrors.length === 0, `no errors in the page${pageErrors.length ? ': ' + pageErrors.join('; ') : ''}`);
} catch (error) {
  console.error(`FAILED: ${error.message}`);
  exitCode = 1;
} finally {
  await browser.close();
  server.kill('SIGTERM');
}
process.exit(exitCode);
