// The page: decodes the chosen image with the browser, turns it gray (BT.601 luma, as erd does
// for colour PNG), hands it to the worker and shows what comes back.
const $ = (id) => document.getElementById(id);
const worker = new Worker('worker.js');
let gray = null, width = 0, height = 0;

function luma(rgba) {
    const g = new Uint8Array(rgba.length / 4);
    for (let i = 0; i < g.length; ++i) {
        const r = rgba[4 * i], gg = rgba[4 * i + 1], b = rgba[4 * i + 2];
        g[i] = r === gg && gg === b ? r : Math.min(255, Math.round(0.299 * r + 0.587 * gg + 0.114 * b));
    }
    return g;
}

function put(canvas, g, w, h) {
    canvas.width = w; canvas.height = h;
    const ctx = canvas.getContext('2d');
    const im = ctx.createImageData(w, h);
    for (let i = 0; i < g.length; ++i) { im.data[4 * i] = im.data[4 * i + 1] = im.data[4 * i + 2] = g[i]; im.data[4 * i + 3] = 255; }
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
    gray = luma(ctx.getImageData(0, 0, width, height).data);
    put($('orig'), gray, width, height);
    $('mesh').innerHTML = '';
    $('run').disabled = false;
    $('status').textContent = `${f.name}: ${width} x ${height}`;
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
        maxError: maxError === '' ? -1 : Number(maxError),
    };
}

$('run').addEventListener('click', () => {
    $('run').disabled = true;
    $('progress').hidden = false; $('bar').value = 0; $('bar').dataset.max = '0';
    $('stage').textContent = 'starting'; $('percent').textContent = '';
    $('status').textContent = 'meshing...';
    worker.postMessage({pixels: gray, width, height, method: $('method').value, density: Number($('density').value), flags: flags()});
});

// A stage with a measured fraction (the greedy insertion) moves the bar; the others show their
// name with the bar at their start.
function progress(stage, fraction) {
    const percent = Math.min(100, Math.floor(fraction * 100));
    $('bar').value = percent;
    $('stage').textContent = stage;
    $('percent').textContent = percent + '%';
}

function timings(rows, total) {
    const t = $('timings');
    t.innerHTML = '<tr><th colspan="2">Time (ms)</th></tr>';
    for (const [name, ms] of rows.concat([['total in the worker', total]])) {
        const tr = t.insertRow();
        tr.insertCell().textContent = name;
        tr.insertCell().textContent = ms.toFixed(1);
    }
}

function link(a, name, blob) { a.href = URL.createObjectURL(blob); a.download = name; a.hidden = false; }

worker.onmessage = (e) => {
    const r = e.data;
    if (r.progress !== undefined) {
        progress(r.progress, r.fraction);
        $('bar').dataset.max = String(Math.max(Number($('bar').dataset.max), $('bar').value));  // what the test reads
        return;
    }
    $('run').disabled = false;
    if (r.ok) progress('done', 1);
    if (!r.ok) { $('status').textContent = 'error: ' + r.error; return; }
    put($('recon'), r.recon, r.width, r.height);
    // The mesh drawing without its white background, over the original.
    $('mesh').innerHTML = r.mesh.replace(/<\?xml[^>]*>/, '').replace(/<rect id="background"[^>]*\/>/, '');
    $('status').innerHTML = `${r.method}: <span id="vertices">${r.vertices}</span> vertices, PSNR <span id="psnr">${r.psnr.toFixed(4)}</span> dB, ${(r.ms / 1000).toFixed(2)} s`;
    const ext = r.method.startsWith('erd') ? 'erd' : 'model';
    link($('dl-model'), 'mesh.' + ext, new Blob([r.model], {type: 'text/plain'}));
    $('dl-model').textContent = '.' + ext;
    link($('dl-svg'), 'mesh.svg', new Blob([r.vector], {type: 'image/svg+xml'}));
    timings(r.timings, r.ms);
    $('recon').toBlob((b) => link($('dl-png'), 'reconstruction.png', b), 'image/png');
};
