// rollingdisk's view: the map of steady motions and the 3D view of a motion, each drawn on
// a 2D canvas (the 3D view by a hand-written perspective projection).  One ES module, with
// two users: the served explorer (explore.js takes its named exports) and the notebook
// widget (anywidget takes its default export, { render }, from rollingdisk.explore.widget).
// It draws what Python computes and nothing else: no physics, no request, nothing loaded
// from elsewhere; both users hand it the same records (rollingdisk.explore.api: the map,
// the steady motion, the simulated track).

// ----------------------------------------------------------------------- map
export const COLORS = { 0: [61, 64, 91], 1: [227, 162, 127], 2: [244, 241, 222] };
const SLIDES = [178, 58, 72];
export const MARGIN = { left: 58, right: 12, top: 14, bottom: 44 };
export const LABELS = { omega30: "\u03c9\u2083\u2080", Omega0: "\u03a9\u2080", r_C: "r_C" };

/** The map's plot box in canvas pixels. */
export function plotBox(canvas) {
  return { x0: MARGIN.left, y0: MARGIN.top, w: canvas.width - MARGIN.left - MARGIN.right,
           h: canvas.height - MARGIN.top - MARGIN.bottom };
}

export function toPixel(m, box, x, y) {
  const [xl, xh] = m.x.range, [yl, yh] = m.y.range;
  return [box.x0 + (x - xl) / (xh - xl) * box.w, box.y0 + (1 - (y - yl) / (yh - yl)) * box.h];
}

export function fromPixel(m, box, px, py) {
  const [xl, xh] = m.x.range, [yl, yh] = m.y.range;
  return [xl + (px - box.x0) / box.w * (xh - xl), yl + (1 - (py - box.y0) / box.h) * (yh - yl)];
}

/**
 * Draw the map `m` (the /api/map record) on `canvas`: the class grid, red where the steady
 * motion needs more friction than `muNow`, the static-equilibrium tilt, the axes and the
 * `selected` point ([theta0, y] or null).  Returns {exist, rolls} (counts of grid points),
 * or null where there is no map.
 */
export function drawMap(canvas, m, muNow, selected) {
  const ctx = canvas.getContext("2d");
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  if (!m) return null;
  const box = plotBox(canvas), nx = m.x.values.length, ny = m.y.values.length;
  // the class grid as an image, one pixel a cell, scaled without smoothing
  const img = new ImageData(nx, ny);
  let rolls = 0, exist = 0;
  for (let j = 0; j < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const code = m.codes[j][i], k = 4 * ((ny - 1 - j) * nx + i);
      const req = m.mu_required[j][i];
      let c = COLORS[code];
      if (code !== 0) {
        exist++;
        if (req !== null && req > muNow) c = SLIDES; else rolls++;
      }
      img.data[k] = c[0]; img.data[k + 1] = c[1]; img.data[k + 2] = c[2]; img.data[k + 3] = 255;
    }
  }
  const off = document.createElement("canvas");
  off.width = nx; off.height = ny;
  off.getContext("2d").putImageData(img, 0, 0);
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(off, box.x0, box.y0, box.w, box.h);
  // static-equilibrium tilt tan(theta0) = h
  if (m.h > 0) {
    const [sx] = toPixel(m, box, m.se_theta0, 0);
    ctx.strokeStyle = "#1f5fbf"; ctx.setLineDash([5, 4]); ctx.lineWidth = 1.2;
    ctx.beginPath(); ctx.moveTo(sx, box.y0); ctx.lineTo(sx, box.y0 + box.h); ctx.stroke();
    ctx.setLineDash([]);
  }
  // axes
  ctx.strokeStyle = "#444"; ctx.lineWidth = 1; ctx.strokeRect(box.x0, box.y0, box.w, box.h);
  ctx.fillStyle = "#222"; ctx.font = "12px system-ui, sans-serif"; ctx.textAlign = "center";
  for (let deg = 0; deg <= 90; deg += 15) {
    const [px] = toPixel(m, box, deg * Math.PI / 180, 0);
    ctx.fillText(String(deg), px, box.y0 + box.h + 15);
    ctx.beginPath(); ctx.moveTo(px, box.y0 + box.h); ctx.lineTo(px, box.y0 + box.h + 4); ctx.stroke();
  }
  ctx.fillText("\u03b8\u2080 (deg)", box.x0 + box.w / 2, box.y0 + box.h + 34);
  ctx.textAlign = "right";
  const [yl, yh] = m.y.range;
  for (let k = 0; k <= 6; k++) {
    const y = yl + (yh - yl) * k / 6, [, py] = toPixel(m, box, 0, y);
    ctx.fillText(Number(y.toPrecision(3)).toString(), box.x0 - 6, py + 4);
    ctx.beginPath(); ctx.moveTo(box.x0 - 4, py); ctx.lineTo(box.x0, py); ctx.stroke();
  }
  ctx.save(); ctx.translate(14, box.y0 + box.h / 2); ctx.rotate(-Math.PI / 2);
  ctx.textAlign = "center"; ctx.fillText(LABELS[m.y.name] || m.y.name, 0, 0); ctx.restore();
  // selected point
  if (selected) {
    const [px, py] = toPixel(m, box, selected[0], selected[1]);
    ctx.strokeStyle = "#000"; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.arc(px, py, 6, 0, 2 * Math.PI); ctx.stroke();
    ctx.strokeStyle = "#fff"; ctx.lineWidth = 1;
    ctx.beginPath(); ctx.arc(px, py, 6, 0, 2 * Math.PI); ctx.stroke();
  }
  return { exist, rolls };
}

/**
 * The map point [theta0, y] under a click `ev` on `canvas` (shown at any CSS size), or null
 * outside the plot box.
 */
export function mapPoint(canvas, m, ev) {
  const rect = canvas.getBoundingClientRect(), box = plotBox(canvas);
  const px = (ev.clientX - rect.left - canvas.clientLeft) * canvas.width / canvas.clientWidth;
  const py = (ev.clientY - rect.top - canvas.clientTop) * canvas.height / canvas.clientHeight;
  if (px < box.x0 || px > box.x0 + box.w || py < box.y0 || py > box.y0 + box.h) return null;
  return fromPixel(m, box, px, py);
}

// -------------------------------------------------------------- steady motion
const FIELDS = [
  ["motion", "motion", null], ["theta0", "\u03b8\u2080 [rad]", 1], ["Omega0", "\u03a9\u2080", 1],
  ["omega0", "\u03c9\u2080 = d\u03c6/dt", 1], ["omega20", "\u03c9\u2082\u2080", 1],
  ["omega30", "\u03c9\u2083\u2080", 1], ["r_C", "r_C", 1], ["r_P", "r_P", 1],
  ["varpi2", "\u03d6\u00b2", 1], ["stable", "stable", null], ["period", "period 2\u03c0/\u03d6", 1],
  ["growth_rate", "growth rate \u221a(\u2212\u03d6\u00b2)", 1],
  ["mu_required", "\u03bc_required = |F_t|/F_z", 1], ["v_C", "speed of C", 1],
];

export function fmt(v) {
  if (v === null || v === undefined) return "\u2013";
  if (typeof v === "number") return Number(v.toPrecision(6)).toString();
  return String(v);
}

/** Append a label and a value to the grid of numbers; the value's element. */
export function addNumber(grid, label, text) {
  const l = document.createElement("span"), v = document.createElement("span");
  l.className = "label"; l.textContent = label; v.textContent = text;
  grid.append(l, v);
  return v;
}

/**
 * Fill `grid` with the numbers of the steady motion `s` (the /api/steady record that
 * exists), each value at full precision in its data-value (shortest round trip), SI values
 * after them for a disk with a physical size.
 */
export function showNumbers(grid, s) {
  for (const [key, label, numeric] of FIELDS) {
    const v = s[key], cell = addNumber(grid, label, fmt(v));
    cell.dataset.field = key;
    cell.dataset.value = v === null ? "" : String(v);
    if (!numeric) cell.dataset.kind = "text";
  }
  if (s.si) {  // a disk with a physical size: SI beside the paper's units
    for (const [label, v] of Object.entries(s.si)) {
      const cell = addNumber(grid, label, fmt(v));
      cell.dataset.field = "si:" + label;
      cell.dataset.value = v === null ? "" : String(v);
    }
  }
}

// --------------------------------------------------------------------- 3D view
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                         a[0] * b[1] - a[1] * b[0]];
const norm = (a) => { const l = Math.hypot(a[0], a[1], a[2]) || 1; return [a[0] / l, a[1] / l, a[2] / l]; };
const LIGHT = norm([0.3, -0.4, 0.9]);
export const BACKGROUND = "#eef1f5";

/** A camera about its target: azimuth, elevation [rad] and distance [radii]. */
export function newCamera() { return { az: -0.9, el: 0.45, dist: 5.5 }; }

function camera(canvas, cam, target) {
  const { az, el, dist } = cam;
  const pos = [target[0] + dist * Math.cos(el) * Math.cos(az),
               target[1] + dist * Math.cos(el) * Math.sin(az), target[2] + dist * Math.sin(el)];
  const f = norm(sub(target, pos)), r = norm(cross(f, [0, 0, 1])), u = cross(r, f);
  const focal = 0.9 * Math.min(canvas.width, canvas.height);
  return {
    pos,
    project(p) {   // perspective: screen = centre + focal * (x, y) / depth
      const d = sub(p, pos), z = dot(d, f);
      if (z < 0.05) return null;
      return [canvas.width / 2 + focal * dot(d, r) / z, canvas.height / 2 - focal * dot(d, u) / z, z];
    },
  };
}

function vec(arr, k) { return [arr[3 * k], arr[3 * k + 1], arr[3 * k + 2]]; }

function pathTarget(tr) {
  let xl = Infinity, xh = -Infinity, yl = Infinity, yh = -Infinity;
  for (let k = 0; k < tr.t.length; k++) {
    xl = Math.min(xl, tr.X_P[k], tr.X_C[k]); xh = Math.max(xh, tr.X_P[k], tr.X_C[k]);
    yl = Math.min(yl, tr.Y_P[k], tr.Y_C[k]); yh = Math.max(yh, tr.Y_P[k], tr.Y_C[k]);
  }
  return { centre: [(xl + xh) / 2, (yl + yh) / 2, 0.3], size: Math.max(xh - xl, yh - yl, 2) };
}

function polyline(ctx, cam, pts, color, width) {
  ctx.strokeStyle = color; ctx.lineWidth = width; ctx.beginPath();
  let pen = false;
  for (const p of pts) {
    const q = cam.project(p);
    if (!q) { pen = false; continue; }
    if (pen) ctx.lineTo(q[0], q[1]); else ctx.moveTo(q[0], q[1]);
    pen = true;
  }
  ctx.stroke();
}

function shade(base, n) {
  const k = 0.55 + 0.45 * Math.max(0, dot(n, LIGHT));
  return `rgb(${Math.round(base[0] * k)},${Math.round(base[1] * k)},${Math.round(base[2] * k)})`;
}

/**
 * Draw frame `frame` of the track `tr` (the /api/simulate record: per stored point t,
 * X_C, Y_C, Z_C, X_P, Y_P and the unit vectors axis, e1, e2 as flat lists; h) on `canvas`
 * as seen by `cam`, following the centre C if `follow`, else looking at the whole path.
 * Returns the index of the frame drawn, or -1 where there is no track (then `empty` is
 * written on the canvas).
 */
export function drawScene(canvas, tr, frame, cam, follow, empty) {
  const ctx = canvas.getContext("2d");
  ctx.fillStyle = BACKGROUND; ctx.fillRect(0, 0, canvas.width, canvas.height);
  if (!tr) {
    ctx.fillStyle = "#888"; ctx.font = "14px system-ui, sans-serif"; ctx.textAlign = "center";
    ctx.fillText(empty || "", canvas.width / 2, canvas.height / 2);
    return -1;
  }
  const k = Math.min(frame, tr.t.length - 1), h = tr.h;
  const C = [tr.X_C[k], tr.Y_C[k], tr.Z_C[k]];
  const whole = pathTarget(tr);
  const target = follow ? [C[0], C[1], 0.3] : whole.centre;
  const view = camera(canvas, cam, target);
  // ground grid, spacing 1 (the radius), around the target
  const g0x = Math.round(target[0]), g0y = Math.round(target[1]), L = 8;
  ctx.lineWidth = 1; ctx.strokeStyle = "#cfd6df";
  for (let i = -L; i <= L; i++) {
    polyline(ctx, view, [[g0x + i, g0y - L, 0], [g0x + i, g0y + L, 0]], "#cfd6df", 1);
    polyline(ctx, view, [[g0x - L, g0y + i, 0], [g0x + L, g0y + i, 0]], "#cfd6df", 1);
  }
  // paths up to now: contact point P (red) and centre C (blue)
  const P = [], Cs = [];
  for (let i = 0; i <= k; i++) {
    P.push([tr.X_P[i], tr.Y_P[i], 0]);
    Cs.push([tr.X_C[i], tr.Y_C[i], tr.Z_C[i]]);
  }
  polyline(ctx, view, P, "#c0392b", 1.6);
  polyline(ctx, view, Cs, "rgba(41, 98, 255, 0.7)", 1.2);
  // the disk: a cylinder of radius 1 and thickness 2h about C along the axis eta;
  // only the faces turned to the camera are drawn (a convex body needs no sorting)
  const eta = vec(tr.axis, k), e1 = vec(tr.e1, k), e2 = vec(tr.e2, k), N = 48;
  const rim = (side, a) => {
    const c = Math.cos(a), s = Math.sin(a);
    return [C[0] + side * h * eta[0] + c * e1[0] + s * e2[0],
            C[1] + side * h * eta[1] + c * e1[1] + s * e2[1],
            C[2] + side * h * eta[2] + c * e1[2] + s * e2[2]];
  };
  const facing = (point, normal) => dot(normal, sub(view.pos, point)) > 0;
  const fill = (pts, color) => {
    const q = pts.map((p) => view.project(p));
    if (q.some((x) => !x)) return;
    ctx.fillStyle = color; ctx.strokeStyle = color; ctx.lineWidth = 0.6;
    ctx.beginPath(); ctx.moveTo(q[0][0], q[0][1]);
    for (const p of q.slice(1)) ctx.lineTo(p[0], p[1]);
    ctx.closePath(); ctx.fill(); ctx.stroke();
  };
  const metal = [176, 184, 196], edge = [120, 128, 140];
  for (let i = 0; i < N; i++) {
    const a0 = 2 * Math.PI * i / N, a1 = 2 * Math.PI * (i + 1) / N, am = (a0 + a1) / 2;
    const n = [0, 1, 2].map((j) => Math.cos(am) * e1[j] + Math.sin(am) * e2[j]);
    const quad = [rim(-1, a0), rim(-1, a1), rim(1, a1), rim(1, a0)];
    if (facing(quad[0], n) || h === 0) fill(quad, shade(edge, n));
  }
  for (const side of [-1, 1]) {
    const n = eta.map((x) => side * x), centre = C.map((x, j) => x + side * h * eta[j]);
    if (!facing(centre, n)) continue;
    const pts = [];
    for (let i = 0; i < N; i++) pts.push(rim(side, 2 * Math.PI * i / N));
    fill(pts, shade(metal, n));
    polyline(ctx, view, [centre, rim(side, 0)], "#b03030", 2.5);   // turns with phi
  }
  // contact point
  const q = view.project([tr.X_P[k], tr.Y_P[k], 0]);
  if (q) { ctx.fillStyle = "#c0392b"; ctx.beginPath(); ctx.arc(q[0], q[1], 4, 0, 2 * Math.PI); ctx.fill(); }
  return k;
}

/** Rotate `cam` by dragging on `canvas`, zoom with the wheel; `redraw()` after each move. */
export function orbit(canvas, cam, redraw) {
  let drag = null;
  canvas.addEventListener("pointerdown", (ev) => { drag = [ev.clientX, ev.clientY]; canvas.setPointerCapture(ev.pointerId); });
  canvas.addEventListener("pointerup", () => { drag = null; });
  canvas.addEventListener("pointermove", (ev) => {
    if (!drag) return;
    cam.az -= (ev.clientX - drag[0]) * 0.01;
    cam.el = Math.min(1.5, Math.max(0.05, cam.el + (ev.clientY - drag[1]) * 0.01));
    drag = [ev.clientX, ev.clientY];
    redraw();
  });
  canvas.addEventListener("wheel", (ev) => {
    ev.preventDefault();
    cam.dist = Math.min(200, Math.max(2, cam.dist * Math.exp(ev.deltaY * 0.001)));
    redraw();
  }, { passive: false });
}

/**
 * Playback of the track that `track()` returns: `player.frame` advances by about 6 time
 * units a second, whatever the number of stored points, and `step(frame)` is called at each
 * animation frame while playing.  `player.play(on)` starts or stops it; whether it plays.
 */
export function playback(track, step) {
  const player = { frame: 0, playing: false };
  let lastTick = null;
  function tick(now) {
    const tr = track();
    if (!player.playing || !tr) return;
    if (lastTick !== null) {
      const dt = (now - lastTick) / 1000, span = tr.t[tr.t.length - 1] || 1;
      const n = Math.max(1, Math.round(dt * 6 / span * (tr.t.length - 1)));
      player.frame = (player.frame + n) % tr.t.length;
      step(player.frame);
    }
    lastTick = now;
    requestAnimationFrame(tick);
  }
  player.play = (on) => {
    player.playing = on && !!track();
    lastTick = null;
    if (player.playing) requestAnimationFrame(tick);
    return player.playing;
  };
  return player;
}

// ------------------------------------------------------------ notebook widget
// anywidget's contract: render({ model, el }).  The model's traits (rollingdisk.explore.widget):
//   disk     {h, radius_m?, time_s?}        the disk; time_s the time unit sqrt(a/g) in s
//   map      the /api/map record, or {}     a click sets `selected` = [theta0, omega30]
//   selected [theta0, omega30] or []
//   motion   the /api/steady record, or {}  the numbers of the selected steady motion
//   frames   the /api/simulate record, or {}: the track played in 3D with a time slider
const PLAY = "\u25b6 play", PAUSE = "\u275a\u275a pause";

function element(parent, tag, props) {
  const e = document.createElement(tag);
  Object.assign(e, props || {});
  parent.appendChild(e);
  return e;
}

function present(record) { return record && Object.keys(record).length > 0 ? record : null; }

function render({ model, el }) {
  el.classList.add("rollingdisk-view");
  const row = element(el, "div");
  Object.assign(row.style, { display: "flex", flexWrap: "wrap", gap: "12px",
                             font: "13px/1.4 system-ui, sans-serif" });
  const fit = { maxWidth: "100%", height: "auto", display: "block", background: "#fff",
                border: "1px solid #ccc" };
  const column = { flex: "0 1 442px", minWidth: "0" };   // a canvas wide, shrinking to fit
  const mapped = present(model.get("map"));
  const cleanups = [];
  const listen = (event, f) => { model.on(event, f); cleanups.push(() => model.off(event, f)); };

  if (mapped) {
    const left = element(row, "div", { className: "rd-left" });
    Object.assign(left.style, column);
    const canvas = element(left, "canvas", { width: 440, height: 380, className: "rd-map" });
    Object.assign(canvas.style, fit, { cursor: "crosshair" });
    const legend = element(left, "div", { className: "rd-legend", textContent:
      "dark: no steady motion \u00b7 orange: unstable \u00b7 light: stable \u00b7 " +
      "dashed: tan \u03b8\u2080 = h" });
    Object.assign(legend.style, { fontSize: "12px", color: "#666", marginTop: "4px" });
    const grid = element(left, "div", { className: "rd-numbers" });
    Object.assign(grid.style, { display: "grid", gridTemplateColumns: "auto auto auto auto",
                                gap: "1px 12px", justifyContent: "start", marginTop: "6px",
                                fontSize: "12px", fontVariantNumeric: "tabular-nums" });
    const drawSelected = () => {
      const sel = model.get("selected");
      drawMap(canvas, model.get("map"), Infinity, sel && sel.length === 2 ? sel : null);
    };
    const numbers = () => {
      const s = present(model.get("motion"));
      grid.innerHTML = "";
      grid.dataset.exists = s ? String(!!s.exists) : "";
      if (!s) addNumber(grid, "click a steady motion on the map", "");
      else if (!s.exists) addNumber(grid, "no steady motion", s.reason);
      else showNumbers(grid, s);
    };
    canvas.addEventListener("click", (ev) => {
      const p = mapPoint(canvas, model.get("map"), ev);
      if (!p) return;
      model.set("selected", p);
      model.save_changes();
      drawSelected();
    });
    listen("change:map", drawSelected);
    listen("change:selected", drawSelected);
    listen("change:motion", numbers);
    drawSelected();
    numbers();
  }

  const right = element(row, "div", { className: "rd-right" });
  Object.assign(right.style, column);
  const view = element(right, "canvas", { width: 440, height: 380, className: "rd-3d" });
  Object.assign(view.style, fit, { cursor: "grab" });
  const bar = element(right, "div");
  Object.assign(bar.style, { display: "flex", gap: "10px", alignItems: "center",
                             marginTop: "6px", flexWrap: "wrap" });
  const button = element(bar, "button", { type: "button", textContent: PLAY });
  const slider = element(bar, "input", { type: "range", min: 0, max: 0, value: 0 });
  Object.assign(slider.style, { flex: "1 1 120px", minWidth: "0" });
  const label = element(bar, "span");
  const followBox = element(element(bar, "label", { textContent: " follow" }), "input",
                            { type: "checkbox", checked: true });
  const cam = newCamera();
  const track = () => present(model.get("frames"));
  const draw = () => {
    const tr = track();
    const k = drawScene(view, tr, player.frame, cam, followBox.checked,
                        mapped ? "click a steady motion on the map" : "no motion to play");
    if (k < 0) { label.textContent = ""; return; }
    const d = model.get("disk") || {};
    label.textContent = `t = ${tr.t[k].toFixed(2)} \u221a(a/g)` +
      (d.time_s ? ` (${(tr.t[k] * d.time_s).toFixed(3)} s)` : "") +
      (tr.theta ? `  \u03b8 = ${tr.theta[k].toFixed(4)}` : "");
  };
  const player = playback(track, (k) => { slider.value = String(k); draw(); });
  const setPlaying = (on) => { button.textContent = player.play(on) ? PAUSE : PLAY; };
  const load = () => {
    const tr = track();
    player.frame = 0;
    slider.max = String(tr ? tr.t.length - 1 : 0);
    slider.value = "0";
    slider.disabled = button.disabled = !tr;
    view.dataset.frames = tr ? String(tr.t.length) : "";
    setPlaying(!!tr);
    draw();
  };
  button.addEventListener("click", () => setPlaying(!player.playing));
  slider.addEventListener("input", () => {
    setPlaying(false);
    player.frame = parseInt(slider.value, 10);
    draw();
  });
  followBox.addEventListener("change", draw);
  orbit(view, cam, draw);
  listen("change:frames", load);
  load();
  return () => { player.play(false); cleanups.forEach((f) => f()); };
}

export default { render };
