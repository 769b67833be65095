// The picture on the page: the original and erd's reconstruction stacked in one box, the
// reconstruction and its mesh shown right of a dividing line the user drags (before | after),
// zoom and pan shared by all three.
//
// The two pictures are canvases at image resolution, placed by one CSS transform (translate, then
// scale s: image pixel (x, y) covers [x, x + 1) x [y, y + 1) scaled, so a vertex at doubled
// coordinates (X, Y), the pixel centre X / 2, sits at X / 2 + 0.5). The mesh is drawn on a canvas
// the size of the box, again at every change of view, so its lines stay one screen pixel wide at
// any zoom. The dividing line is a fraction of the box's width and stays put while the picture
// moves under it.
//
// Input: drag (one pointer) pans, or moves the line when it starts on the line; two pointers pinch;
// the wheel zooms at the cursor; double-click zooms in there. Keys, when the box has the focus:
// + and - zoom at the centre, 0 fits, the arrows pan (Shift: further).
'use strict';

class Viewer {
    constructor(box, {orig, recon, reconLayer, overlay, divider, onView}) {
        Object.assign(this, {box, orig, recon, reconLayer, overlay, divider, onView});
        this.w = 0; this.h = 0;               // image size
        this.s = 1; this.tx = 0; this.ty = 0;  // view: screen = t + s * image
        this.fitted = true;                    // follow the box's size until the user zooms or pans
        this.split = 0.5;
        this.mesh = null;
        this.show = {mesh: true, edges: true};
        this.pointers = new Map();
        this.frame = 0;
        new ResizeObserver(() => this.resized()).observe(box);
        this.listen();
    }

    // A new picture: w x h pixels, shown whole.
    setImage(w, h) {
        this.w = w; this.h = h;
        this.box.style.aspectRatio = `${w} / ${h}`;
        this.mesh = null;
        this.fit();
    }

    // {vertices (doubled x y), faces (i j k), constraints (i j)}, or null.
    setMesh(mesh) { this.mesh = mesh; this.redraw(); }

    setShow(show) { Object.assign(this.show, show); this.redraw(); }

    // f in [0, 1]: the fraction of the box's width left of the line (the original's side).
    setSplit(f) {
        this.split = Math.min(1, Math.max(0, f));
        const pc = (this.split * 100).toFixed(2) + '%';
        this.reconLayer.style.clipPath = `inset(0 0 0 ${pc})`;
        this.divider.style.left = pc;
        this.redraw();
        this.onView?.();
    }

    fitScale() { return this.w ? Math.min(this.box.clientWidth / this.w, this.box.clientHeight / this.h) : 1; }

    fit() { this.fitted = true; this.s = this.fitScale(); this.place(); }

    // Scales the view by `factor` around the box point (sx, sy), within [fit, 32 image pixels a pixel].
    zoomAt(factor, sx, sy) {
        const lo = this.fitScale(), hi = Math.max(32, lo * 4);
        const s = Math.min(hi, Math.max(lo, this.s * factor));
        this.tx = sx - (sx - this.tx) * (s / this.s);
        this.ty = sy - (sy - this.ty) * (s / this.s);
        this.s = s;
        this.fitted = Math.abs(s - lo) < 1e-9;
        this.place();
    }

    panBy(dx, dy) { this.tx += dx; this.ty += dy; this.place(); }  // at the fit, place() centres it again

    // Keeps the picture in the box: centred along an axis where it is smaller than the box, else
    // with no gap at either side; then moves the canvases and redraws the mesh.
    place() {
        const bw = this.box.clientWidth, bh = this.box.clientHeight;
        const clamp = (t, size, room) => size <= room ? (room - size) / 2 : Math.min(0, Math.max(room - size, t));
        this.tx = clamp(this.tx, this.s * this.w, bw);
        this.ty = clamp(this.ty, this.s * this.h, bh);
        const transform = `translate(${this.tx}px, ${this.ty}px) scale(${this.s})`;
        const rendering = this.s >= 3 ? 'pixelated' : 'auto';  // see the pixels once they are large
        for (const c of [this.orig, this.recon]) {
            c.style.width = this.w + 'px'; c.style.height = this.h + 'px';
            c.style.transform = transform; c.style.imageRendering = rendering;
        }
        this.redraw();
        this.onView?.();
    }

    resized() {
        const dpr = window.devicePixelRatio || 1;
        this.overlay.width = Math.round(this.box.clientWidth * dpr);
        this.overlay.height = Math.round(this.box.clientHeight * dpr);
        if (this.fitted) this.fit(); else this.place();
    }

    redraw() {
        if (!this.frame) this.frame = requestAnimationFrame(() => { this.frame = 0; this.draw(); });
    }

    draw() {
        const ctx = this.overlay.getContext('2d');
        ctx.restore();  // the last draw's clip
        ctx.save();
        const dpr = this.overlay.width / Math.max(1, this.box.clientWidth);
        ctx.setTransform(1, 0, 0, 1, 0, 0);
        ctx.clearRect(0, 0, this.overlay.width, this.overlay.height);
        const m = this.mesh;
        if (!m || !(this.show.mesh || this.show.edges)) return;
        ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
        const bw = this.box.clientWidth;
        ctx.beginPath();
        ctx.rect(this.split * bw, 0, bw, this.box.clientHeight);  // erd's side of the line only
        ctx.clip();
        const v = m.vertices, n = v.length / 2, xy = new Float32Array(v.length);
        for (let i = 0; i < n; ++i) {
            xy[2 * i] = this.tx + this.s * (v[2 * i] / 2 + 0.5);
            xy[2 * i + 1] = this.ty + this.s * (v[2 * i + 1] / 2 + 0.5);
        }
        const segment = (a, b) => { ctx.moveTo(xy[2 * a], xy[2 * a + 1]); ctx.lineTo(xy[2 * b], xy[2 * b + 1]); };
        if (this.show.mesh) {
            // Each edge once: an inner edge is in two faces, once in each direction; a border edge
            // (both ends on the same side of the image) is in one.
            const X = 2 * this.w - 2, Y = 2 * this.h - 2;
            const border = (a, b) => (v[2 * a] === v[2 * b] && (v[2 * a] === 0 || v[2 * a] === X)) ||
                                     (v[2 * a + 1] === v[2 * b + 1] && (v[2 * a + 1] === 0 || v[2 * a + 1] === Y));
            const f = m.faces;
            ctx.beginPath();
            for (let i = 0; i < f.length; i += 3)
                for (let k = 0; k < 3; ++k) {
                    const a = f[i + k], b = f[i + (k + 1) % 3];
                    if (a < b || border(a, b)) segment(a, b);
                }
            ctx.lineJoin = 'round';
            ctx.strokeStyle = 'rgba(8, 12, 24, 0.45)'; ctx.lineWidth = 2.2; ctx.stroke();  // a dark halo: visible on light and dark
            ctx.strokeStyle = 'rgba(170, 225, 255, 0.9)'; ctx.lineWidth = 0.9; ctx.stroke();
        }
        if (this.show.edges && m.constraints.length) {
            const c = m.constraints;
            ctx.beginPath();
            for (let i = 0; i < c.length; i += 2) segment(c[i], c[i + 1]);
            ctx.lineCap = 'round';
            ctx.strokeStyle = 'rgba(20, 0, 10, 0.5)'; ctx.lineWidth = 4.5; ctx.stroke();
            ctx.strokeStyle = '#ff3d71'; ctx.lineWidth = 2.5; ctx.stroke();
        }
    }

    point(e) {
        const r = this.box.getBoundingClientRect();
        return {x: e.clientX - r.left, y: e.clientY - r.top};
    }

    listen() {
        const box = this.box;
        box.addEventListener('pointerdown', (e) => {
            if (e.pointerType === 'mouse' && e.button !== 0) return;
            box.setPointerCapture(e.pointerId);
            const onLine = this.pointers.size === 0 && this.divider.contains(e.target);
            this.pointers.set(e.pointerId, {...this.point(e), onLine});
            box.classList.toggle('dragging', !onLine);
            if (onLine) this.setSplit(this.point(e).x / box.clientWidth);
        });
        box.addEventListener('pointermove', (e) => {
            const p = this.pointers.get(e.pointerId);
            if (!p) return;
            const q = this.point(e);
            if (this.pointers.size === 1) {
                if (p.onLine) this.setSplit(q.x / box.clientWidth);
                else this.panBy(q.x - p.x, q.y - p.y);
            } else if (this.pointers.size === 2) {  // pinch: scale by the change of distance, pan by the midpoint's move
                const [a, b] = [...this.pointers.values()];
                const other = a === p ? b : a;
                const d0 = Math.hypot(p.x - other.x, p.y - other.y), d1 = Math.hypot(q.x - other.x, q.y - other.y);
                const m0 = {x: (p.x + other.x) / 2, y: (p.y + other.y) / 2}, m1 = {x: (q.x + other.x) / 2, y: (q.y + other.y) / 2};
                if (d0 > 0) this.zoomAt(d1 / d0, m0.x, m0.y);
                this.panBy(m1.x - m0.x, m1.y - m0.y);
            }
            p.x = q.x; p.y = q.y;
        });
        const up = (e) => { this.pointers.delete(e.pointerId); if (!this.pointers.size) box.classList.remove('dragging'); };
        box.addEventListener('pointerup', up);
        box.addEventListener('pointercancel', up);
        box.addEventListener('wheel', (e) => {
            e.preventDefault();
            const q = this.point(e);
            const step = e.deltaMode === 1 ? 0.05 : e.deltaMode === 2 ? 1 : 0.0015;
            this.zoomAt(Math.exp(-e.deltaY * step), q.x, q.y);
        }, {passive: false});
        box.addEventListener('dblclick', (e) => { const q = this.point(e); this.zoomAt(2, q.x, q.y); });
        box.addEventListener('keydown', (e) => {
            if (e.altKey || e.ctrlKey || e.metaKey) return;
            const cx = box.clientWidth / 2, cy = box.clientHeight / 2, step = e.shiftKey ? 160 : 40;
            const keys = {
                '+': () => this.zoomAt(1.25, cx, cy), '=': () => this.zoomAt(1.25, cx, cy),
                '-': () => this.zoomAt(0.8, cx, cy), '_': () => this.zoomAt(0.8, cx, cy), '0': () => this.fit(),
                ArrowLeft: () => this.panBy(step, 0), ArrowRight: () => this.panBy(-step, 0),
                ArrowUp: () => this.panBy(0, step), ArrowDown: () => this.panBy(0, -step),
            };
            if (!keys[e.key]) return;
            e.preventDefault();
            keys[e.key]();
        });
    }
}
