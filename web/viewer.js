// The 3D view: the model (vertex-coloured by the texture), the model cut open, the field's axis
// glyphs and the sketch curves, with orbit controls and ray casts for drawing.
import * as THREE from 'three';
import {OrbitControls} from 'three/addons/controls/OrbitControls.js';
import {GLTFLoader} from 'three/addons/loaders/GLTFLoader.js';
import {computeBoundsTree, acceleratedRaycast} from 'three-mesh-bvh';

// Ray casts on models of a few hundred thousand triangles, at pointer-move rate.
THREE.BufferGeometry.prototype.computeBoundsTree = computeBoundsTree;
THREE.Mesh.prototype.raycast = acceleratedRaycast;

const UNTEXTURED = 0.72 ** 2.2;  // the server's grey, linear
// sRGB byte -> linear: vertex colours are linear in three.js (and in glTF).
const SRGB_TO_LINEAR = Float32Array.from({length: 256}, (_, i) => {
  const c = i / 255;
  return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
});
const AXIS_COLORS = [new THREE.Color(0.9, 0.12, 0.1), new THREE.Color(0.1, 0.7, 0.15), new THREE.Color(0.12, 0.3, 0.95)];

export class Viewer {
  constructor(container) {
    this.container = container;
    // preserveDrawingBuffer: screenshots (tests, the gallery) read what is on screen.
    this.renderer = new THREE.WebGLRenderer({antialias: true, preserveDrawingBuffer: true});
    this.renderer.setPixelRatio(window.devicePixelRatio);
    container.append(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0x2b2f36);
    this.camera = new THREE.PerspectiveCamera(35, 1, 0.01, 100);
    this.scene.add(this.camera);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x404048, 1.6));
    const key = new THREE.DirectionalLight(0xffffff, 1.8);
    key.position.set(0.5, 1, 1);
    this.camera.add(key);  // the light follows the view
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.requestRender());
    this.loader = new GLTFLoader();
    this.material = new THREE.MeshStandardMaterial({vertexColors: true, roughness: 0.85, metalness: 0});
    this.model = null;
    this.cutModel = null;
    this.glyphs = new THREE.LineSegments(new THREE.BufferGeometry(),
                                         new THREE.LineBasicMaterial({vertexColors: true, depthTest: true}));
    this.curves = new THREE.Group();
    this.stroke = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({color: 0xffe14d}));
    this.scene.add(this.glyphs, this.curves, this.stroke);
    this.raycaster = new THREE.Raycaster();
    new ResizeObserver(() => this.resize()).observe(container);
    this.resize();
    this.renderer.setAnimationLoop(() => this.frame());
  }

  resize() {
    const {clientWidth: w, clientHeight: h} = this.container;
    if (!w || !h) return;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  requestRender() { this.dirty = true; }

  frame() {
    if (!this.dirty) return;
    this.dirty = false;
    this.renderer.render(this.scene, this.camera);
    this.rendered = (this.rendered || 0) + 1;
  }

  async loadMesh(url) {
    const gltf = await this.loader.loadAsync(url);
    let mesh = null;
    gltf.scene.traverse((o) => { if (o.isMesh && !mesh) mesh = o; });
    if (!mesh) throw new Error('the model file holds no mesh');
    mesh.geometry.computeBoundsTree();
    return mesh;
  }

  // The model as the server's display mesh, untextured, framed by its bounds [[min], [max]].
  async showModel(url, bounds) {
    const mesh = await this.loadMesh(url);
    const count = mesh.geometry.attributes.position.count;
    mesh.geometry.setAttribute('color', new THREE.BufferAttribute(new Float32Array(count * 3).fill(UNTEXTURED), 3));
    mesh.material = this.material;
    if (this.model) this.scene.remove(this.model);
    this.model = mesh;
    this.scene.add(mesh);
    this.hideCut();
    this.frameBounds(bounds);
    this.requestRender();
  }

  frameBounds([min, max]) {
    this.bounds = new THREE.Box3(new THREE.Vector3(...min), new THREE.Vector3(...max));
    const center = this.bounds.getCenter(new THREE.Vector3());
    const radius = this.bounds.getSize(new THREE.Vector3()).length() / 2;
    this.camera.near = radius / 100;
    this.camera.far = radius * 100;
    this.camera.position.copy(center).add(new THREE.Vector3(0.55, 0.35, 1).normalize().multiplyScalar(radius * 2.5));
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
  }

  // Vertex colours from the server's rgb8 bytes (one RGB triple per display vertex).
  setColors(bytes) {
    if (!this.model) return;
    const rgb = new Uint8Array(bytes);
    const colors = this.model.geometry.attributes.color;
    if (rgb.length !== colors.count * 3) throw new Error('the colours do not match the model');
    for (let i = 0; i < rgb.length; ++i) colors.array[i] = SRGB_TO_LINEAR[rgb[i]];
    colors.needsUpdate = true;
    this.requestRender();
  }

  async showCut(url) {
    const mesh = await this.loadMesh(url);
    mesh.material = this.material;
    if (this.cutModel) this.scene.remove(this.cutModel);
    this.cutModel = mesh;
    this.scene.add(mesh);
    if (this.model) this.model.visible = false;
    this.requestRender();
  }

  hideCut() {
    if (this.cutModel) this.scene.remove(this.cutModel);
    this.cutModel = null;
    if (this.model) this.model.visible = true;
    this.requestRender();
  }

  // The field's axes as short red / green / blue sticks (GET /api/field/glyphs).
  setGlyphs(data) {
    const length = data.spacing * 0.42;
    const positions = [], colors = [];
    for (const g of data.glyphs) {
      const p = new THREE.Vector3(...g.position);
      ['x', 'y', 'z'].forEach((axis, a) => {
        const end = new THREE.Vector3(...g[axis]).multiplyScalar(length).add(p);
        positions.push(...p.toArray(), ...end.toArray());
        colors.push(...AXIS_COLORS[a].toArray(), ...AXIS_COLORS[a].toArray());
      });
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
    geometry.setAttribute('color', new THREE.Float32BufferAttribute(colors, 3));
    this.glyphs.geometry.dispose();
    this.glyphs.geometry = geometry;
    this.curves.clear();
    for (const curve of data.curves) {
      const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(curve.samples.map((p) => new THREE.Vector3(...p))),
                                  new THREE.LineBasicMaterial({color: 0xffe14d}));
      this.curves.add(line);
    }
    this.requestRender();
  }

  showGlyphs(visible) {
    this.glyphs.visible = visible;
    this.requestRender();
  }

  setStroke(points) {
    this.stroke.geometry.dispose();
    this.stroke.geometry = new THREE.BufferGeometry().setFromPoints(points);
    this.requestRender();
  }

  pointer(event) {
    const rect = this.renderer.domElement.getBoundingClientRect();
    return new THREE.Vector2(((event.clientX - rect.left) / rect.width) * 2 - 1,
                             -((event.clientY - rect.top) / rect.height) * 2 + 1);
  }

  // The visible model's surface point under the pointer, or null.
  hitSurface(event) {
    const target = this.cutModel || this.model;
    if (!target) return null;
    this.raycaster.setFromCamera(this.pointer(event), this.camera);
    this.raycaster.firstHitOnly = true;
    const hit = this.raycaster.intersectObject(target)[0];
    return hit ? hit.point.clone() : null;
  }

  // The point under the pointer on the plane normal to `axis` at `fraction` of the box, inside the box.
  hitPlane(event, axis, fraction) {
    if (!this.bounds) return null;
    const a = 'xyz'.indexOf(axis);
    const normal = new THREE.Vector3().setComponent(a, 1);
    const offset = THREE.MathUtils.lerp(this.bounds.min.getComponent(a), this.bounds.max.getComponent(a), fraction);
    const plane = new THREE.Plane(normal, -offset);
    this.raycaster.setFromCamera(this.pointer(event), this.camera);
    const point = this.raycaster.ray.intersectPlane(plane, new THREE.Vector3());
    return point && this.bounds.containsPoint(point) ? point : null;
  }
}
