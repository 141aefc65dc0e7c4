// Drawing sketch curves with the pointer: a drag on the model (or on the cutting plane) becomes a
// polyline in world space, sent to the server as one curve; undo and redo replay the curves.

// Points closer than this fraction of the model's size are dropped while drawing.
const MIN_SPACING = 0.006;

export class SketchPen {
  // hit(event) -> THREE.Vector3 | null; finish(points) is called with the stroke (>= 2 points).
  constructor(viewer, {hit, finish}) {
    this.viewer = viewer;
    this.hit = hit;
    this.finish = finish;
    this.enabled = false;
    this.points = [];
    const canvas = viewer.renderer.domElement;
    canvas.addEventListener('pointerdown', (e) => this.down(e));
    canvas.addEventListener('pointermove', (e) => this.move(e));
    canvas.addEventListener('pointerup', (e) => this.up(e));
  }

  setEnabled(enabled) {
    this.enabled = enabled;
    this.viewer.controls.enabled = !enabled;  // a drag draws instead of orbiting
    this.viewer.container.classList.toggle('drawing', enabled);
  }

  down(event) {
    if (!this.enabled || event.button !== 0) return;
    const p = this.hit(event);
    if (!p) return;
    this.points = [p];
    this.drawing = true;
    event.target.setPointerCapture(event.pointerId);
  }

  move(event) {
    if (!this.drawing) return;
    const p = this.hit(event);
    if (!p) return;
    const size = this.viewer.bounds.getSize(p.clone()).length();
    if (p.distanceTo(this.points[this.points.length - 1]) < MIN_SPACING * size) return;
    this.points.push(p);
    this.viewer.setStroke(this.points);
  }

  up(event) {
    if (!this.drawing) return;
    this.drawing = false;
    event.target.releasePointerCapture(event.pointerId);
    const points = this.points;
    this.points = [];
    this.viewer.setStroke([]);
    if (points.length >= 2) this.finish(points);
  }
}

// The curves as the server knows them (ids), and what undo took back.
export class SketchHistory {
  constructor() {
    this.done = [];    // {id, body}
    this.undone = [];  // bodies
  }
  added(id, body) {
    this.done.push({id, body});
    this.undone = [];
  }
  reset(ids = []) {
    this.done = ids.map((id) => ({id, body: null}));
    this.undone = [];
  }
  canUndo() { return this.done.length > 0; }
  canRedo() { return this.undone.length > 0; }
}
