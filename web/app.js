// The page: decodes the chosen image with the browser, hands its RGB samples to the worker (which
// meshes it gray when its channels are equal everywhere or "gray" is checked, in colour otherwise,
// as erd generate does) and shows what comes back.
const $ = (id) => document.getElementById(id);
const worker = new Worker('worker.js');
let rgb = null, width = 0, height = 0;

// The RGB samples of the browser's RGBA decode (alpha dropped, as erd drops it).
function rgbOf(rgba) {
    const out = new Uint8Array(rgba.length / 4 * 3);
    for (let i = 0, j = 0; i < rgba.length; i += 4, j += 3) { out[j] = rgba[i]; out[j + 1] = rgba[i + 1]; out[j + 2] = rgba[i + 2]; }
    return out;
}

function isGray(s) {
    for (let i = 0; i < s.length; i += 3) if (s[i] !== s[i + 1] || s[i] !== s[i + 2]) return false;
    return true;
}

// Draws w x h pixels of `channels` (1 or 3) samples each.
function put(canvas, s, w, h, channels) {
    canvas.width = w; canvas.height = h;
    const ctx = canvas.getContext('2d');
    const im = ctx.createImageData(w, h);
    for (let i = 0, n = w * h; i < n; ++i) {
        for (let c = 0; c < 3; ++c) im.data[4 * i + c] = s[channels * i + (channels === 3 ? c : 0)];
        im.data[4 * i + 3] = 255;
    }
    ctx.putImageData(im, 0, 0);
}

$('file').addEventListener('change', async () => {
    const f = $('file').files[0];
    if (!f) return;
    $('run').disabled = true;
    const bmp = await createImageBitmap(f, {colorSpaceConversion: 'none', premultiplyAlpha: 'none'});
    width = bmp.width; height = bmp.height;
    const c = new OffscreenCanvas(width, height);
    const ctx = c.getContext('2d');
    ctx.drawImage(bmp, 0, 0);
    rgb = rgbOf(ctx.getImageData(0, 0, width, height).data);
    put($('orig'), rgb, width, height, 3);
    $('mesh').innerHTML = '';
    $('run').disabled = false;
    $('status').textContent = `${f.name}: ${width} x ${height}, ${isGray(rgb) ? 'gray' : 'colour'}`;
});

// --thesis sets the flags it implies in the form (edges soft, wedge fit 0), as the preset does
// on the command line, where later flags still win; unchecking restores erd's defaults.
$('thesis').addEventListener('change', () => {
    const on = $('thesis').checked;
    $('edges').value = on ? '1' : '0';
    $('wedge-fit').value = on ? '0' : '6';
});

function flags() {
    const maxError = $('max-error').value.trim();
    return {
        edges: Number($('edges').value), thesis: $('thesis').checked ? 1 : 0, wedgeRule: Number($('wedge-rule').value),
        wedgeFit: Number($('wedge-fit').value), psnr: Number($('psnr-stop').value) || 0,
        maxError: maxError === '' ? -1 : Number(maxError), gray: $('gray').checked ? 1 : 0,
    };
}

$('run').addEventListener('click', () => {
    $('run').disabled = true;
    for (const id of ['dl-model', 'dl-svg', 'dl-png']) $(id).hidden = true;  // until this run's files are ready
    $('progress').hidden = false; $('bar').value = 0; $('bar').dataset.max = '0';
    $('stage').textContent = 'starting'; $('percent').textContent = '';
    $('status').textContent = 'meshing...';
    $('mesh').innerHTML = '';
    worker.postMessage({pixels: rgb, width, height, method: $('method').value, density: Number($('density').value), flags: flags()});
});

// A stage with a measured fraction (the greedy insertion) moves the bar; the others show their
// name with the bar at their start.
function progress(stage, fraction) {
    const percent = Math.min(100, Math.floor(fraction * 100));
    $('bar').value = percent;
    $('stage').textContent = stage;
    $('percent').textContent = percent + '%';
}

// The worker's stage times: the meshing's, then the files'.
function timings(rows) {
    const t = $('timings');
    if (!t.rows.length) t.innerHTML = '<tr><th colspan="2">Time (ms)</th></tr>';
    for (const [name, ms] of rows) {
        const tr = t.insertRow();
        tr.insertCell().textContent = name;
        tr.insertCell().textContent = ms.toFixed(1);
    }
}

function link(a, name, blob) { a.href = URL.createObjectURL(blob); a.download = name; a.hidden = false; }

let method = '';
worker.onmessage = (e) => {
    const r = e.data;
    if (r.progress !== undefined) {
        progress(r.progress, r.fraction);
        $('bar').dataset.max = String(Math.max(Number($('bar').dataset.max), $('bar').value));  // what the test reads
        return;
    }
    if (!r.ok && !r.files) { $('run').disabled = false; $('status').textContent = 'error: ' + r.error; return; }
    if (r.files) {  // the downloads, written after the mesh
        $('run').disabled = false;
        progress('done', 1);
        // The mesh drawing without its white background, over the original.
        $('mesh').innerHTML = r.files.mesh.replace(/<\?xml[^>]*>/, '').replace(/<rect id="background"[^>]*\/>/, '');
        const ext = method.startsWith('erd') ? 'erd' : 'model';
        link($('dl-model'), 'mesh.' + ext, new Blob([r.files.model], {type: 'text/plain'}));
        $('dl-model').textContent = '.' + ext;
        link($('dl-svg'), 'mesh.svg', new Blob([r.files.vector], {type: 'image/svg+xml'}));
        timings(r.timings.concat([['files in the worker', r.ms]]));
        $('recon').toBlob((b) => link($('dl-png'), 'reconstruction.png', b), 'image/png');
        return;
    }
    method = r.method;
    progress('writing the files', 1);
    put($('recon'), r.recon, r.width, r.height, r.channels);
    $('status').innerHTML = `${r.method}, ${r.channels === 3 ? 'colour' : 'gray'}: <span id="vertices">${r.vertices}</span> vertices, ${r.channels === 3 ? 'RGB ' : ''}PSNR <span id="psnr">${r.psnr.toFixed(4)}</span> dB, ${r.edges ? `edges <span id="edge-kinds">${r.edges}</span>, ` : ''}${(r.ms / 1000).toFixed(2)} s`;
    $('timings').innerHTML = '';
    timings(r.timings.concat([['mesh in the worker', r.ms]]));
};
