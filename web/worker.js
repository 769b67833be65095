// Runs erd (erd.js + erd.wasm, built by `make web`) off the page's thread. Message in:
// {pixels: Uint8Array (gray), width, height, method, density, flags: {edges, thesis, wedgeRule,
// wedgeFit, psnr, maxError}}; out: {progress: stage, fraction} while it runs (posted by the
// module itself), then {ok, ...results} or {ok: false, error}.
importScripts('build/erd.js');
const ready = createErd({locateFile: (file) => 'build/' + file});
onmessage = async (e) => {
    const erd = await ready;
    const {pixels, width, height, method, density, flags} = e.data;
    const ptr = erd._malloc(pixels.length);
    erd.HEAPU8.set(pixels, ptr);
    const t0 = performance.now();
    const rc = erd.ccall('erd_mesh', 'number',
                         ['number', 'number', 'number', 'string', 'number', 'number', 'number', 'number', 'number', 'number', 'number'],
                         [ptr, width, height, method, density, flags.edges, flags.thesis, flags.wedgeRule, flags.wedgeFit,
                          flags.psnr, flags.maxError]);
    const ms = performance.now() - t0;
    erd._free(ptr);
    if (rc !== 0) { postMessage({ok: false, error: erd.UTF8ToString(erd._erd_error())}); return; }
    const recon = erd.HEAPU8.slice(erd._erd_reconstruction(), erd._erd_reconstruction() + width * height);
    const timings = erd.UTF8ToString(erd._erd_timings()).trim().split('\n').map((l) => {
        const i = l.lastIndexOf(' ');
        return [l.slice(0, i), Number(l.slice(i + 1))];
    });
    postMessage({
        ok: true, ms, timings, width, height, method,
        psnr: erd._erd_psnr(), vertices: erd._erd_vertices(), recon,
        model: erd.UTF8ToString(erd._erd_model_text()),
        vector: erd.UTF8ToString(erd._erd_vector_svg()),
        mesh: erd.UTF8ToString(erd._erd_mesh_svg()),
    }, [recon.buffer]);
};
