// Runs erd (erd.js + erd.wasm, built by `make web`) off the page's thread, one job at a time. The
// page stops a job it no longer wants by terminating this worker (a wasm call cannot be
// interrupted from outside), so nothing here checks for cancellation.
// Messages in:
//   {builtin: {width, height}}: the opening picture (erd_builtin); out {builtin: pixels (RGB)}.
//   {id, pixels: Uint8Array (RGB, interleaved), width, height, method, density, flags: {edges,
//    thesis, wedgeRule, wedgeFit, psnr, maxError, gray}}: a mesh. Out: {progress: stage, fraction}
//    while it runs (posted by the module itself); then {id, ok: true, ms, timings, psnr, vertices,
//    channels, edges (an ERD model's edge kinds, e.g. "hard, 75 soft"; "" otherwise), recon (the
//    reconstruction, `channels` samples a pixel), mesh: {vertices (Int32Array,
//    doubled x y), faces (Uint32Array, i j k), constraints (Uint32Array, i j)}} as soon as the
//    mesh and its reconstruction are there; then {id, files: {model, vector}, ms, timings} once
//    the downloads are written. A failure: {id, ok: false, error}.
importScripts('build/erd.js');
const ready = createErd({locateFile: (file) => 'build/' + file});

function timings(erd) {
    return erd.UTF8ToString(erd._erd_timings()).trim().split('\n').map((l) => {
        const i = l.lastIndexOf(' ');
        return [l.slice(0, i), Number(l.slice(i + 1))];
    });
}

// A copy of n elements of type T at byte address ptr of the module's memory.
const copy = (erd, T, ptr, n) => new T(erd.HEAPU8.buffer, ptr, n).slice();

onmessage = async (e) => {
    const erd = await ready;
    if (e.data.builtin) {
        const {width, height} = e.data.builtin;
        const ptr = erd._erd_builtin(width, height);
        postMessage({builtin: erd.HEAPU8.slice(ptr, ptr + width * height * 3)});
        return;
    }
    const {id, pixels, width, height, method, density, flags} = e.data;
    const ptr = erd._malloc(pixels.length);
    erd.HEAPU8.set(pixels, ptr);
    const t0 = performance.now();
    const rc = erd.ccall('erd_mesh', 'number',
                         ['number', 'number', 'number', 'string', 'number', 'number', 'number', 'number', 'number', 'number', 'number', 'number'],
                         [ptr, width, height, method, density, flags.edges, flags.thesis, flags.wedgeRule, flags.wedgeFit,
                          flags.psnr, flags.maxError, flags.gray]);
    const ms = performance.now() - t0;
    erd._free(ptr);
    if (rc !== 0) { postMessage({id, ok: false, error: erd.UTF8ToString(erd._erd_error())}); return; }
    const channels = erd._erd_channels();
    const recon = erd.HEAPU8.slice(erd._erd_reconstruction(), erd._erd_reconstruction() + width * height * channels);
    const nv = erd._erd_vertices();
    const mesh = {
        vertices: copy(erd, Int32Array, erd._erd_mesh_vertices(), 2 * nv),
        faces: copy(erd, Uint32Array, erd._erd_mesh_faces(), 3 * erd._erd_faces()),
        constraints: copy(erd, Uint32Array, erd._erd_mesh_constraints(), 2 * erd._erd_constraints()),
    };
    postMessage({id, ok: true, ms, timings: timings(erd), width, height, method, channels, psnr: erd._erd_psnr(), vertices: nv,
                 edges: erd.UTF8ToString(erd._erd_edge_kinds()), recon, mesh},
                [recon.buffer, mesh.vertices.buffer, mesh.faces.buffer, mesh.constraints.buffer]);
    const t1 = performance.now();
    if (erd._erd_files() !== 0) { postMessage({id, ok: false, error: erd.UTF8ToString(erd._erd_error())}); return; }
    postMessage({
        id, ms: performance.now() - t1, timings: timings(erd),
        files: {model: erd.UTF8ToString(erd._erd_model_text()), vector: erd.UTF8ToString(erd._erd_vector_svg())},
    });
};
