// The page: opens with erd's own test picture meshed, and meshes again whenever the picture or a
// setting changes. Pictures come from the file chooser, a drop or a paste; the browser decodes
// them and the worker (worker.js) meshes their RGB samples gray when the channels are equal
// everywhere or "Gray" is checked, in colour otherwise, as erd generate does.
//
// One job at a time: a new request while the worker is still busy (meshing, or writing the
// downloads) terminates that worker and hands the job to a spare one, started in advance, since
// a running wasm call cannot be stopped any other way. Slider moves are debounced.
//
// For the browser test (web/test/page_test.mjs) the body carries data-state (starting, meshing,
// files, idle, error), data-meshes (results shown) and data-cancelled (jobs stopped).
'use strict';
const $ = (id) => document.getElementById(id);

// The density slider's stops, percent of the pixels: 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 a decade.
const DENSITIES = [0.05, 0.06, 0.08, 0.1, 0.12, 0.15, 0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.8, 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10];
// The opening picture: erd synth's image at this size, coloured (erd_builtin), meshed at this density.
const OPENING = {name: 'erd-synth.png', width: 480, height: 320};
const MAX_PIXELS = 1 << 20;  // larger pictures are scaled down to this unless "Full size" is checked
const DEBOUNCE_MS = 150;

const viewer = new Viewer($('viewer'), {
    orig: $('orig'), recon: $('recon'), reconLayer: $('recon-layer'), overlay: $('overlay'), divider: $('divider'),
    onView: () => {
        $('zoom-level').textContent = Math.round(viewer.s * 100) + '%';
        $('split').value = String(Math.round(viewer.split * 100));
    },
});
viewer.setSplit(0.3);  // through the first disc: half of it as it is, half as erd has it

let picture = null;  // {name, file (to read again at full size), rgb, width, height, note, builtin}
let density = 0.5;

// ---- Workers ----------------------------------------------------------------------------------
let jobId = 0;
function startWorker() {
    const rec = {w: new Worker('worker.js'), busy: false};
    rec.w.onmessage = (e) => { if (rec === worker) fromWorker(e.data); };
    rec.w.onerror = (e) => {
        if (rec !== worker) return;
        e.preventDefault();
        rec.busy = false;
        fail('erd could not start in this browser (' + (e.message || 'the worker failed') + ')');
    };
    return rec;
}
let worker = startWorker(), spare = null;

function stopJob() {
    if (!worker.busy) return;
    worker.w.terminate();
    worker = spare || startWorker();
    spare = null;
    document.body.dataset.cancelled = String(Number(document.body.dataset.cancelled) + 1);
}

// ---- Pictures ---------------------------------------------------------------------------------
// The RGB samples of the browser's RGBA decode (alpha dropped, as erd drops it).
function rgbOf(rgba) {
    const out = new Uint8Array(rgba.length / 4 * 3);
    for (let i = 0, j = 0; i < rgba.length; i += 4, j += 3) { out[j] = rgba[i]; out[j + 1] = rgba[i + 1]; out[j + 2] = rgba[i + 2]; }
    return out;
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

function setPicture(p) {
    picture = p;
    hideError();
    put($('orig'), p.rgb, p.width, p.height, 3);
    $('recon').width = p.width; $('recon').height = p.height;  // cleared until the first result
    viewer.setImage(p.width, p.height);
    for (const id of ['dl-model', 'dl-svg', 'dl-png', 'dl-original']) $(id).hidden = true;
    if (p.builtin) $('orig').toBlob((b) => link($('dl-original'), p.name, b), 'image/png');
    $('vertices').textContent = '–'; $('psnr').textContent = '–'; $('time').textContent = '';
    $('what').textContent = `${p.name}, ${p.width} x ${p.height}${p.note ? ` (${p.note})` : ''}:`;
    run();
}

const base = (name) => name.replace(/\.[^.]*$/, '') || 'image';

// A File (chosen, dropped or pasted): decoded by the browser, scaled down to MAX_PIXELS unless
// "Full size" is checked. A file the browser cannot decode gets the error line; the picture on
// the page stays.
async function openFile(file) {
    const name = file.name || 'pasted image';
    let bmp;
    try {
        bmp = await createImageBitmap(file, {colorSpaceConversion: 'none', premultiplyAlpha: 'none'});
    } catch (e) {
        const type = file.type ? `, ${file.type}` : '';
        fail(`${name}: not an image this browser can read (${file.size} bytes${type}). Try a PNG or JPEG file.`);
        return;
    }
    let {width, height} = bmp, note = '';
    if (width * height > MAX_PIXELS && !$('full-size').checked) {
        const k = Math.sqrt(MAX_PIXELS / (width * height));
        const w = Math.max(1, Math.floor(width * k)), h = Math.max(1, Math.floor(height * k));
        note = `scaled from ${width} x ${height} for speed`;
        bmp = await createImageBitmap(bmp, {resizeWidth: w, resizeHeight: h, resizeQuality: 'high'});
        width = w; height = h;
    }
    const c = new OffscreenCanvas(width, height);
    const ctx = c.getContext('2d');
    ctx.drawImage(bmp, 0, 0);
    setPicture({name, file, rgb: rgbOf(ctx.getImageData(0, 0, width, height).data), width, height, note, builtin: false});
}

$('file').addEventListener('change', () => { if ($('file').files[0]) openFile($('file').files[0]); $('file').value = ''; });
$('full-size').addEventListener('change', () => { if (picture?.file) openFile(picture.file); });

// Drop anywhere on the page; while a file is dragged over it, the picture says where it goes.
let dragDepth = 0;
document.addEventListener('dragenter', (e) => { if (e.dataTransfer?.types.includes('Files')) { ++dragDepth; document.body.classList.add('drag'); } });
document.addEventListener('dragleave', () => { if (dragDepth > 0 && --dragDepth === 0) document.body.classList.remove('drag'); });
document.addEventListener('dragover', (e) => e.preventDefault());
document.addEventListener('drop', (e) => {
    e.preventDefault();
    dragDepth = 0; document.body.classList.remove('drag');
    const f = e.dataTransfer?.files[0];
    if (f) openFile(f);
    else fail('Nothing to mesh in what was dropped: drop an image file.');
});

// Paste: an image on the clipboard (a copied picture or file); text pasted into a field is the field's.
document.addEventListener('paste', (e) => {
    const files = [...(e.clipboardData?.files || [])];
    const f = files.find((x) => x.type.startsWith('image/')) || files[0];
    if (f) { e.preventDefault(); openFile(f); return; }
    if (!e.target.closest?.('input, select, textarea')) fail('Nothing to mesh on the clipboard: copy an image itself (not its address) and paste again.');
});

// ---- Settings ---------------------------------------------------------------------------------
function showDensity() {
    const n = picture ? Math.round(density / 100 * picture.width * picture.height) : 0;
    $('density-out').textContent = `${density} %` + (n ? ` · ${n.toLocaleString('en')} vertices` : '');
}

function nearestStop(d) {
    let best = 0;
    DENSITIES.forEach((x, i) => { if (Math.abs(Math.log(x / d)) < Math.abs(Math.log(DENSITIES[best] / d))) best = i; });
    return best;
}

let timer = 0;
function later(ms) { clearTimeout(timer); timer = setTimeout(run, ms); }

$('density-slider').addEventListener('input', () => {
    density = DENSITIES[Number($('density-slider').value)];
    $('density').value = String(density);
    showDensity();
    later(DEBOUNCE_MS);
});
$('density-slider').addEventListener('change', () => later(0));  // the drag (or key) is over: now
$('density').addEventListener('change', () => {
    const d = Number($('density').value);
    if (!(d > 0 && d <= 100)) { $('density').value = String(density); return; }
    density = d;
    $('density-slider').value = String(nearestStop(d));
    showDensity();
    later(0);
});
$('method').addEventListener('change', () => later(0));
for (const id of ['edges', 'wedge-rule', 'wedge-fit', 'psnr-stop', 'max-error', 'gray']) $(id).addEventListener('change', () => later(0));
// --thesis sets the flags it implies in the form (edges soft, wedge fit 0), as the preset does on
// the command line, where later flags still win; unchecking restores erd's defaults.
$('thesis').addEventListener('change', () => {
    const on = $('thesis').checked;
    $('edges').value = on ? '1' : '0';
    $('wedge-fit').value = on ? '0' : '6';
    later(0);
});

function flags() {
    const maxError = $('max-error').value.trim();
    return {
        edges: Number($('edges').value), thesis: $('thesis').checked ? 1 : 0, wedgeRule: Number($('wedge-rule').value),
        wedgeFit: Number($('wedge-fit').value), psnr: Number($('psnr-stop').value) || 0,
        maxError: maxError === '' ? -1 : Number(maxError), gray: $('gray').checked ? 1 : 0,
    };
}

// The erd generate command that makes the same mesh from the same file.
function commandLine() {
    const f = flags(), m = $('method').value, input = picture.name.includes('.') ? picture.name : picture.name + '.png';
    const out = base(input) + (m.startsWith('erd') ? '.erd' : '.model');
    const args = ['erd generate -m', m, '-i', /^[\w.@%+=:,/-]+$/.test(input) ? input : `'${input.replace(/'/g, `'\\''`)}'`, '-d', density];
    if (f.thesis) args.push('--thesis');
    if (m.startsWith('erd')) {
        if (f.edges !== (f.thesis ? 1 : 0)) args.push('--edges', ['auto', 'soft', 'hard'][f.edges]);
        if (f.wedgeRule !== 1) args.push('-w', f.wedgeRule);
        if (f.wedgeFit !== (f.thesis ? 0 : 6)) args.push('--wedge-fit', f.wedgeFit);
    }
    if (f.psnr > 0) args.push('--psnr', f.psnr);
    if (f.maxError >= 0) args.push('--max-error', f.maxError);
    if (f.gray) args.push('--gray');
    return args.concat(['-o', out]).join(' ');
}

for (const id of ['show-mesh', 'show-edges'])
    $(id).addEventListener('change', () => viewer.setShow({mesh: $('show-mesh').checked, edges: $('show-edges').checked}));
$('split').addEventListener('input', () => viewer.setSplit(Number($('split').value) / 100));
const centre = () => [$('viewer').clientWidth / 2, $('viewer').clientHeight / 2];
$('zoom-in').addEventListener('click', () => viewer.zoomAt(1.5, ...centre()));
$('zoom-out').addEventListener('click', () => viewer.zoomAt(1 / 1.5, ...centre()));
$('zoom-fit').addEventListener('click', () => viewer.fit());

// ---- Runs -------------------------------------------------------------------------------------
function setState(s) { document.body.dataset.state = s; }

function run() {
    clearTimeout(timer);
    if (!picture) return;
    stopJob();
    hideError();
    const id = ++jobId;
    worker.busy = true;
    setState('meshing');
    $('result').classList.add('stale');
    for (const a of ['dl-model', 'dl-svg', 'dl-png']) $(a).hidden = true;  // until this run's files are ready
    $('bar').value = 0; $('bar').dataset.max = '0';
    $('stage').textContent = 'starting';
    showDensity();
    $('cli').textContent = commandLine();
    const {rgb, width, height} = picture;
    worker.w.postMessage({id, pixels: rgb, width, height, method: $('method').value, density, flags: flags()});
}

// A stage with a measured fraction (the greedy insertion) moves the bar; the others show their name.
function progress(stage, fraction) {
    const percent = Math.min(100, Math.floor(fraction * 100));
    $('bar').value = percent;
    $('bar').dataset.max = String(Math.max(Number($('bar').dataset.max), percent));  // what the test reads
    $('stage').textContent = fraction > 0 && fraction < 1 ? `${stage} ${percent}%` : stage;
}

// The worker's stage times, appended to the table.
function timings(rows, clear) {
    const t = $('timings');
    if (clear) while (t.rows.length) t.deleteRow(0);
    for (const [name, ms] of rows) {
        const tr = t.insertRow();
        tr.insertCell().textContent = name;
        tr.insertCell().textContent = ms.toFixed(1);
    }
}

function link(a, name, blob) {
    if (a.href) URL.revokeObjectURL(a.href);
    a.href = URL.createObjectURL(blob); a.download = name; a.hidden = false;
}

function fromWorker(r) {
    if (r.builtin) {  // unless the user was quicker with a picture of their own
        if (!picture) setPicture({name: OPENING.name, rgb: r.builtin, width: OPENING.width, height: OPENING.height, note: '', builtin: true});
        return;
    }
    if (r.progress !== undefined) { progress(r.progress, r.fraction); return; }
    if (r.id !== jobId) return;
    if (r.ok === false) {
        worker.busy = false;
        fail('erd: ' + r.error);
        return;
    }
    const name = base(picture.name);
    if (r.files) {
        const ext = $('result').dataset.method.startsWith('erd') ? 'erd' : 'model';  // the downloads, written after the mesh
        worker.busy = false;
        setState('idle');
        $('stage').textContent = '';
        link($('dl-model'), `${name}.${ext}`, new Blob([r.files.model], {type: 'text/plain'}));
        $('dl-model').textContent = `model (.${ext})`;
        link($('dl-svg'), `${name}.svg`, new Blob([r.files.vector], {type: 'image/svg+xml'}));
        timings(r.timings.concat([['files in the worker', r.ms]]), false);
        $('recon').toBlob((b) => link($('dl-png'), `${name}-erd.png`, b), 'image/png');
        if (!spare) spare = startWorker();  // ready for the next cancel
        return;
    }
    put($('recon'), r.recon, r.width, r.height, r.channels);
    viewer.setMesh(r.mesh);
    $('result').classList.remove('stale');
    const colour = r.channels === 3 ? 'colour' : 'gray';
    $('what').textContent = `${picture.name}, ${r.width} x ${r.height} ${colour}${picture.note ? ` (${picture.note})` : ''}, ${r.method.toUpperCase()}:`;
    $('vertices').textContent = r.vertices.toLocaleString('en');
    $('vertices').dataset.value = String(r.vertices);
    $('psnr').textContent = r.psnr.toFixed(2);
    $('psnr').dataset.value = r.psnr.toFixed(4);  // as erd psnr prints it
    $('psnr').title = `${r.psnr.toFixed(4)} dB${r.channels === 3 ? ' (RGB-PSNR, as erd psnr)' : ''}`;
    // An ERD model's edge kinds (issue 44): its own kind, and how many edges are of the other.
    $('edge-kinds').textContent = r.edges || '';
    $('edge-kinds-figure').hidden = !r.edges;
    $('time').textContent = `${(r.ms / 1000).toFixed(2)} s`;
    $('stage').textContent = 'writing the downloads';
    $('result').dataset.channels = String(r.channels);
    $('result').dataset.method = r.method;
    $('result').dataset.ms = String(Math.round(r.ms));
    timings(r.timings.concat([['mesh in the worker', r.ms]]), true);
    setState('files');
    document.body.dataset.meshes = String(Number(document.body.dataset.meshes) + 1);
}

function fail(message) {
    setState('error');
    $('stage').textContent = '';
    $('error').textContent = message;
    $('error').hidden = false;
    $('result').classList.remove('stale');
}
function hideError() { $('error').hidden = true; }

// ---- Opening ----------------------------------------------------------------------------------
$('density').value = String(density);
$('density-slider').value = String(nearestStop(density));
worker.w.postMessage({builtin: {width: OPENING.width, height: OPENING.height}});
