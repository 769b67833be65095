// A .glb seen in three.js (npm three) in Debian's chromium (playwright-core), saved as a PNG: the
// picture of docs/img. The page is served from this folder on a free port; the camera looks at
// the mesh's bounding box from the south-west, above, with a sun and a sky light; the faces are
// shaded flat (the file has no normals) and, without vertex colours in the file, tinted by height
// (green low, brown, white high) in the page.
//   node tools/gltf/picture.mjs MESH.glb OUT.png [WIDTH HEIGHT]
import { createServer } from 'node:http';
import { readFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = dirname(fileURLToPath(import.meta.url));
const [glb, out, w = '1200', h = '800'] = process.argv.slice(2);
const page_html = `<!doctype html><html><body style="margin:0;background:#dfe6ec">
<script type="importmap">{"imports":{"three":"/node_modules/three/build/three.module.js","three/addons/":"/node_modules/three/examples/jsm/"}}</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
const W = ${Number(w)}, H = ${Number(h)};
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setSize(W, H);
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xdfe6ec);
scene.add(new THREE.HemisphereLight(0xe8eeff, 0x3a3028, 0.9));
const sun = new THREE.DirectionalLight(0xfff4e0, 2.6);
scene.add(sun);
new GLTFLoader().load('/mesh.glb', (gltf) => {
  scene.add(gltf.scene);
  gltf.scene.traverse((o) => {
    if (!o.isMesh) return;
    const g = o.geometry, p = g.attributes.position;
    if (!g.attributes.color) {
      g.computeBoundingBox();
      const lo = g.boundingBox.min.y, hi = g.boundingBox.max.y, col = new Float32Array(3 * p.count);
      const ramp = [[0.20, 0.42, 0.22], [0.45, 0.55, 0.28], [0.58, 0.45, 0.30], [0.55, 0.50, 0.46], [0.95, 0.95, 0.95]];
      for (let i = 0; i < p.count; ++i) {
        const t = Math.min(0.999, Math.max(0, (p.getY(i) - lo) / (hi - lo || 1))) * (ramp.length - 1), k = Math.floor(t), f = t - k;
        for (let c = 0; c < 3; ++c) col[3 * i + c] = ramp[k][c] * (1 - f) + ramp[k + 1][c] * f;
      }
      g.setAttribute('color', new THREE.BufferAttribute(col, 3));
      o.material.vertexColors = true;
      o.material.color.set(0xffffff);
    }
    o.material.flatShading = true;
    o.material.needsUpdate = true;
  });
  const box = new THREE.Box3().setFromObject(gltf.scene), c = box.getCenter(new THREE.Vector3()), s = box.getSize(new THREE.Vector3());
  const r = Math.max(s.x, s.z);
  const camera = new THREE.PerspectiveCamera(35, W / H, r / 100, r * 10);
  camera.position.set(c.x - 0.55 * r, c.y + 0.75 * r, c.z + 0.95 * r);
  camera.lookAt(c);
  sun.position.set(c.x - r, c.y + 0.6 * r, c.z - 0.4 * r);
  sun.target.position.copy(c);
  scene.add(sun.target);
  renderer.render(scene, camera);
  document.title = 'ready';
}, undefined, (e) => { document.title = 'error: ' + e; });
</script></body></html>`;

const server = createServer((req, res) => {
    try {
        if (req.url === '/' || req.url === '/index.html') return res.end(page_html);
        if (req.url === '/mesh.glb') return res.end(readFileSync(resolve(glb)));
        const path = join(here, decodeURIComponent(req.url));
        if (!path.startsWith(join(here, 'node_modules'))) { res.statusCode = 404; return res.end(); }
        res.setHeader('Content-Type', path.endsWith('.js') ? 'text/javascript' : 'application/octet-stream');
        res.end(readFileSync(path));
    } catch { res.statusCode = 404; res.end(); }
});
await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
const port = server.address().port;
const browser = await chromium.launch({ executablePath: process.env.CHROMIUM || '/usr/bin/chromium', args: ['--no-sandbox', '--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'] });
try {
    const page = await browser.newPage({ viewport: { width: Number(w), height: Number(h) } });
    await page.goto(`http://127.0.0.1:${port}/`);
    await page.waitForFunction(() => document.title !== '', null, { timeout: 120000 });
    const title = await page.title();
    if (title !== 'ready') throw new Error(title);
    await page.locator('canvas').screenshot({ path: out });
    console.log(`wrote ${out}`);
} finally {
    await browser.close();
    server.close();
}
