// Runs erd (erd.js + erd.wasm, built by `make web`) off the page's thread. Message in:
// {pixels: Uint8Array (RGB, interleaved), width, height, method, density, flags: {edges, thesis,
// wedgeRule, wedgeFit, psnr, maxError, gray}}. Out: {progress: stage, fraction} while it runs
// (posted by the module itself); then {ok: true, ms, timings, psnr, vertices, channels, edges (an
// ERD model's edge kinds, "" otherwise), recon (the reconstruction, `channels` samples a pixel), ...} as soon as the mesh and its reconstruction are
// there; then {files: {model, vector, mesh}, ms, timings} once the downloads are written. A failure:
// {ok: false, error}.
importScripts('build/erd.js');
const ready = createErd({locateFile: (file) => 'build/' + file});

function timings(erd) {
    return erd.UTF8ToString(erd._erd_timings()).trim().split('\n').map((l) => {
        const i = l.lastIndexOf(' ');
        return [l.slice(0, i), Number(l.slice(i + 1))];
    });
}

onmessage = async (e) => {
    const erd = await ready;
    const {pixels, width, height, method, density, flags} = e.data;
    const ptr = erd._malloc(pixels.length);
    erd.HEAPU8.set(pixels, ptr);
    const t0 = performance.now();
    const rc = erd.ccall('erd_mesh', 'number',
                         ['number', 'number', 'number', 'string', 'number', 'number', 'number', 'number', 'number', 'number', 'number', 'number'],
                         [ptr, width, height, method, density, flags.edges, flags.thesis, flags.wedgeRule, flags.wedgeFit,
                          flags.psnr, flags.maxError, flags.gray]);
    const ms = performance.now() - t0;
    erd._free(ptr);
    if (rc !== 0) { postMessage({ok: false, error: erd.UTF8ToString(erd._erd_error())}); return; }
    const channels = erd._erd_channels();
    const recon = erd.HEAPU8.slice(erd._erd_reconstruction(), erd._erd_reconstruction() + width * height * channels);
    postMessage({ok: true, ms, timings: timings(erd), width, height, method, channels, psnr: erd._erd_psnr(),
                 vertices: erd._erd_vertices(), edges: erd.UTF8ToString(erd._erd_edge_kinds()), recon}, [recon.buffer]);
    const t1 = performance.now();
    if (erd._erd_files() !== 0) { postMessage({ok: false, error: erd.UTF8ToString(erd._erd_error())}); return; }
    postMessage({
        ms: performance.now() - t1, timings: timings(erd),
        files: {model: erd.UTF8ToString(erd._erd_model_text()), vector: erd.UTF8ToString(erd._erd_vector_svg()),
                mesh: erd.UTF8ToString(erd._erd_mesh_svg())},
    });
};
