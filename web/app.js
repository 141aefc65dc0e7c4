// texsynth studio's page: controls on the left, the 3D view on the right, everything through the
// JSON API and its event stream. `window.studio` exposes the page's state for tests.
import * as api from './api.js';
import {Viewer} from './viewer.js';
import {SketchPen, SketchHistory} from './sketch.js';

const $ = (id) => document.getElementById(id);
const state = {
  scene: null,           // GET /api/scene
  job: {preview: null, cut: null},  // the newest job per lane: older results are ignored
  glyphRevision: -1,     // the field revision the glyphs show
  previews: 0,           // results shown, per kind (tests wait on these)
  cuts: 0,
  lastResult: null,
  ready: false,
};
window.studio = state;

const viewer = new Viewer($('view'));
const history = new SketchHistory();

function status(text) { $('status').textContent = text; }
function showError(error) {
  $('error').textContent = error ? String(error.message || error) : '';
  if (error) console.error(error);
}
async function attempt(action) {
  try {
    showError(null);
    return await action();
  } catch (error) {
    showError(error);
  }
}

function fillSelect(select, entries, chosen) {
  select.replaceChildren(...entries.map((e) => new Option(e.group === 'uploads' ? `${e.name} (upload)` : e.name, e.id)));
  if (chosen) select.value = chosen;
}

async function loadCatalog() {
  const catalog = await api.getJson('/api/catalog');
  fillSelect($('mesh-select'), catalog.meshes, state.scene?.mesh?.id);
  fillSelect($('exemplar-select'), catalog.exemplars, state.scene?.exemplar);
}

async function loadScene() {
  state.scene = await api.getJson('/api/scene');
  const texture = state.scene.texture;
  $('method-select').value = texture.method;
  $('tiles').value = texture.tiles;
  if (state.scene.exemplar) $('exemplar-image').src = `/api/exemplars/${state.scene.exemplar}/image`;
  if (!state.scene.mesh) {
    status('Choose a mesh to begin.');
    return;
  }
  status(`Loading ${state.scene.mesh.name}…`);
  await viewer.showModel('/api/mesh.glb', state.scene.mesh.bounds);
  history.reset(state.scene.curves);
  updateButtons();
  await refreshGlyphs();
  const m = state.scene.mesh;
  status(`${m.name}: ${m.vertices.toLocaleString()} vertices (${m.display_vertices.toLocaleString()} shown). ` +
         'Texture it, or draw curves to design the field.');
}

async function refreshGlyphs() {
  const glyphs = await api.getJson('/api/field/glyphs?across=16');
  viewer.setGlyphs(glyphs);
  state.glyphRevision = glyphs.revision;
  state.glyphCount = glyphs.glyphs.length;
  state.curveCount = glyphs.curves.length;
}

function textureBody() {
  return {method: $('method-select').value, exemplar: $('exemplar-select').value, tiles: Number($('tiles').value)};
}

async function preview() {
  // The lazy solid refines what this camera sees first.
  const answer = await api.sendJson('POST', '/api/preview', {...textureBody(), camera: viewer.camera.position.toArray()});
  state.job.preview = answer.job;
  status(`Texturing with ${answer.texture.method}…`);
  if (cutEnabled()) requestCut();
}

function cutEnabled() { return $('cut-toggle').checked; }

let cutTimer = null;
function requestCut() {
  clearTimeout(cutTimer);  // a dragged slider asks once it pauses; the server drops stale cuts anyway
  cutTimer = setTimeout(() => attempt(async () => {
    const answer = await api.sendJson('POST', '/api/cut', {
      axis: $('cut-axis').value, position: Number($('cut-position').value), ...textureBody()});
    state.job.cut = answer.job;
  }), 60);
}

async function addCurve(points) {
  const body = {on: $('draw-target').value, points: points.map((p) => [p.x, p.y, p.z])};
  if (body.on === 'plane') {
    const axis = $('cut-axis').value;
    body.plane = {normal: ['x', 'y', 'z'].map((a) => (a === axis ? 1 : 0))};
  }
  if ($('tangent-axis').value) body.tangent_axis = $('tangent-axis').value;
  if ($('normal-axis').value && $('normal-axis').value !== $('tangent-axis').value)
    body.normal_axis = $('normal-axis').value;
  const answer = await api.sendJson('POST', '/api/sketch/curves', body);
  history.added(answer.id, body);
  state.lastCurve = answer;
  updateButtons();
  await refreshGlyphs();
  status(`Curve ${answer.id}: field updated in ${(answer.seconds * 1000).toFixed(0)} ms.`);
  if ($('method-select').value === 'lazy' && state.previews > 0) await preview();
}

async function undo() {
  const last = history.done[history.done.length - 1];
  if (!last) return;
  if (!last.body) {  // a loaded curve: keep its JSON for redo
    const sketch = await api.getJson('/api/sketch');
    last.body = sketch.curves[history.done.length - 1];
  }
  await api.sendJson('DELETE', `/api/sketch/curves/${last.id}`);
  history.done.pop();
  history.undone.push(last.body);
  updateButtons();
  await refreshGlyphs();
}

async function redo() {
  const body = history.undone.pop();
  if (!body) return;
  const answer = await api.sendJson('POST', '/api/sketch/curves', body);
  history.done.push({id: answer.id, body});
  updateButtons();
  await refreshGlyphs();
}

function updateButtons() {
  $('undo-button').disabled = !history.canUndo();
  $('redo-button').disabled = !history.canRedo();
}

async function onResult(result) {
  if (result.job !== state.job[result.kind]) return;  // superseded
  if (result.mesh !== state.scene?.mesh?.id) return;
  if (result.kind === 'preview') {
    viewer.setColors(await api.getBytes(result.url));
    state.previews += 1;
    const done = `${result.method}: ${result.vertices.toLocaleString()} vertices in ${result.seconds.toFixed(2)} s`;
    status({fast: `Fast preview (tile-deform, ${result.seconds.toFixed(2)} s); refining…`,
            visible: `The side facing you refined (${result.seconds.toFixed(1)} s); refining the rest…`}[result.stage] ||
           `${done}.`);
  } else if (result.kind === 'cut' && cutEnabled()) {
    await viewer.showCut(result.url);
    state.cuts += 1;
    status(`Cut at ${result.axis} = ${result.position.toFixed(2)} (${result.method}) in ${result.seconds.toFixed(2)} s.`);
  }
  state.lastResult = result;
}

function onJob(job) {
  if (job.id !== state.job[job.lane]) return;
  if (job.state === 'failed') showError(job.error);
  if (job.state === 'done' || job.state === 'failed') $('progress').value = 0;
}

function onProgress(p) {
  if (p.job !== state.job.preview && p.job !== state.job.cut) return;
  $('progress').value = p.total > 0 ? p.done / p.total : 0;
  $('status').textContent = `${p.stage} (${p.done}/${p.total})`;
}

function wire() {
  $('mesh-select').addEventListener('change', () => attempt(async () => {
    await api.sendJson('POST', '/api/scene', {mesh: $('mesh-select').value});
    $('cut-toggle').checked = false;
    await loadScene();
  }));
  $('exemplar-select').addEventListener('change', () => attempt(async () => {
    await api.sendJson('POST', '/api/scene', {exemplar: $('exemplar-select').value});
    $('exemplar-image').src = `/api/exemplars/${$('exemplar-select').value}/image`;
    await preview();  // choosing an exemplar shows it at once
  }));
  $('mesh-upload').addEventListener('change', (e) => attempt(async () => {
    const entry = await api.upload('mesh', e.target.files[0]);
    await api.sendJson('POST', '/api/scene', {mesh: entry.id});
    await loadCatalog();
    await loadScene();
  }));
  $('exemplar-upload').addEventListener('change', (e) => attempt(async () => {
    const entry = await api.upload('exemplar', e.target.files[0]);
    await loadCatalog();
    $('exemplar-select').value = entry.id;
    $('exemplar-select').dispatchEvent(new Event('change'));
  }));
  $('preview-button').addEventListener('click', () => attempt(preview));
  $('method-select').addEventListener('change', () => state.previews > 0 && attempt(preview));
  $('draw-toggle').addEventListener('change', (e) => pen.setEnabled(e.target.checked));
  $('glyph-toggle').addEventListener('change', (e) => viewer.showGlyphs(e.target.checked));
  $('undo-button').addEventListener('click', () => attempt(undo));
  $('redo-button').addEventListener('click', () => attempt(redo));
  $('save-sketch').addEventListener('click', () => attempt(() => api.exportFile({format: 'sketch'})));
  $('load-sketch').addEventListener('change', (e) => attempt(async () => {
    const response = await fetch('/api/sketch', {method: 'PUT', body: await e.target.files[0].text()});
    if (!response.ok) throw new Error((await response.json()).error);
    history.reset((await response.json()).curves);
    updateButtons();
    await refreshGlyphs();
  }));
  $('cut-toggle').addEventListener('change', () => (cutEnabled() ? requestCut() : viewer.hideCut()));
  $('cut-axis').addEventListener('change', () => cutEnabled() && requestCut());
  $('cut-position').addEventListener('input', () => cutEnabled() && requestCut());
  for (const button of document.querySelectorAll('[data-export]'))
    button.addEventListener('click', () => attempt(async () => {
      status(`Exporting ${button.dataset.export}…`);
      const name = await api.exportFile({format: button.dataset.export, ...(button.dataset.export === 'glb' ||
                                         button.dataset.export === 'vdb' ? textureBody() : {})});
      status(`Saved ${name}.`);
    }));
}

const pen = new SketchPen(viewer, {
  hit: (event) => ($('draw-target').value === 'plane'
      ? viewer.hitPlane(event, $('cut-axis').value, Number($('cut-position').value))
      : viewer.hitSurface(event)),
  finish: (points) => attempt(() => addCurve(points)),
});

api.listen({
  result: (r) => attempt(() => onResult(r)),
  job: onJob,
  progress: onProgress,
  disconnected: () => status('Lost the connection to texsynth studio; retrying…'),
});

wire();
attempt(async () => {
  await loadScene();
  await loadCatalog();
  state.ready = true;
});
