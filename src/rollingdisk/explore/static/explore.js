// rollingdisk explore: the page's script.  It draws what the server computes and nothing
// else: no physics here, every number comes from /api/map, /api/steady and /api/simulate
// (the rollingdisk library).  The 3D view is a 2D canvas with a hand-written perspective
// projection; nothing is loaded from the network.
"use strict";

const $ = (id) => document.getElementById(id);
const COLORS = { 0: [61, 64, 91], 1: [227, 162, 127], 2: [244, 241, 222] };
const SLIDES = "rgba(178, 58, 72, 0.85)";
const MARGIN = { left: 58, right: 12, top: 14, bottom: 44 };
const LABELS = { omega30: "\u03c9\u2083\u2080", Omega0: "\u03a9\u2080", r_C: "r_C" };
const YMAX_DEFAULT = { "theta0-omega30": 3, "theta0-Omega0": 3, "theta0-r_C": 2 };

const state = {
  map: null,        // the /api/map payload
  selected: null,   // {theta0, name, value}
  steady: null,     // the /api/steady payload
  traj: null,       // the /api/simulate payload
  frame: 0,
  playing: false,
  cam: { az: -0.9, el: 0.45, dist: 5.5 },
};

// ------------------------------------------------------------------ requests
function showError(message) {
  const box = $("error");
  box.textContent = message;
  box.hidden = !message;
}

async function api(path, params) {
  const url = path + "?" + new URLSearchParams(params).toString();
  const res = await fetch(url);
  const body = await res.json();
  if (!res.ok) throw new Error(body.error || res.statusText);
  return body;
}

function diskParams() {
  return { ground: $("ground").value, h: $("h").value };
}

// ----------------------------------------------------------------------- map
function plotBox(canvas) {
  return { x0: MARGIN.left, y0: MARGIN.top, w: canvas.width - MARGIN.left - MARGIN.right,
           h: canvas.height - MARGIN.top - MARGIN.bottom };
}

function toPixel(box, x, y) {
  const m = state.map;
  const [xl, xh] = m.x.range, [yl, yh] = m.y.range;
  return [box.x0 + (x - xl) / (xh - xl) * box.w, box.y0 + (1 - (y - yl) / (yh - yl)) * box.h];
}

function fromPixel(box, px, py) {
  const m = state.map;
  const [xl, xh] = m.x.range, [yl, yh] = m.y.range;
  return [xl + (px - box.x0) / box.w * (xh - xl), yl + (1 - (py - box.y0) / box.h) * (yh - yl)];
}

function mu() { return parseFloat($("mu").value); }

function drawMap() {
  const canvas = $("map"), ctx = canvas.getContext("2d"), m = state.map;
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  if (!m) return;
  const box = plotBox(canvas), nx = m.x.values.length, ny = m.y.values.length;
  // the class grid as an image, one pixel a cell, scaled without smoothing
  const img = new ImageData(nx, ny), muNow = mu();
  let rolls = 0, exist = 0;
  for (let j = 0; j < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const code = m.codes[j][i], k = 4 * ((ny - 1 - j) * nx + i);
      const req = m.mu_required[j][i];
      let c = COLORS[code];
      if (code !== 0) {
        exist++;
        if (req !== null && req > muNow) c = [178, 58, 72]; else rolls++;
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
    const [sx] = toPixel(box, m.se_theta0, 0);
    ctx.strokeStyle = "#1f5fbf"; ctx.setLineDash([5, 4]); ctx.lineWidth = 1.2;
    ctx.beginPath(); ctx.moveTo(sx, box.y0); ctx.lineTo(sx, box.y0 + box.h); ctx.stroke();
    ctx.setLineDash([]);
  }
  // axes
  ctx.strokeStyle = "#444"; ctx.lineWidth = 1; ctx.strokeRect(box.x0, box.y0, box.w, box.h);
  ctx.fillStyle = "#222"; ctx.font = "12px system-ui, sans-serif"; ctx.textAlign = "center";
  for (let deg = 0; deg <= 90; deg += 15) {
    const [px] = toPixel(box, deg * Math.PI / 180, 0);
    ctx.fillText(String(deg), px, box.y0 + box.h + 15);
    ctx.beginPath(); ctx.moveTo(px, box.y0 + box.h); ctx.lineTo(px, box.y0 + box.h + 4); ctx.stroke();
  }
  ctx.fillText("\u03b8\u2080 (deg)", box.x0 + box.w / 2, box.y0 + box.h + 34);
  ctx.textAlign = "right";
  const [yl, yh] = m.y.range;
  for (let k = 0; k <= 6; k++) {
    const y = yl + (yh - yl) * k / 6, [, py] = toPixel(box, 0, y);
    ctx.fillText(Number(y.toPrecision(3)).toString(), box.x0 - 6, py + 4);
    ctx.beginPath(); ctx.moveTo(box.x0 - 4, py); ctx.lineTo(box.x0, py); ctx.stroke();
  }
  ctx.save(); ctx.translate(14, box.y0 + box.h / 2); ctx.rotate(-Math.PI / 2);
  ctx.textAlign = "center"; ctx.fillText(LABELS[m.y.name] || m.y.name, 0, 0); ctx.restore();
  // selected point
  const sel = state.selected;
  if (sel && sel.name === m.y.name) {
    const [px, py] = toPixel(box, sel.theta0, sel.value);
    ctx.strokeStyle = "#000"; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.arc(px, py, 6, 0, 2 * Math.PI); ctx.stroke();
    ctx.strokeStyle = "#fff"; ctx.lineWidth = 1;
    ctx.beginPath(); ctx.arc(px, py, 6, 0, 2 * Math.PI); ctx.stroke();
  }
  const muText = muNow.toFixed(2);
  $("map-summary").textContent = exist === 0
    ? "no steady motion anywhere on this map"
    : `${m.ground} ground, h = ${m.h}: at \u03bc = ${muText}, ${rolls} of the ${exist} ` +
      `steady motions on this map roll (\u03bc \u2265 \u03bc_required = |F_t|/F_z)` +
      (m.ground === "smooth" ? "; smooth ground exerts no friction force, \u03bc plays no part" : "");
  canvas.dataset.ready = "1";
}

async function loadMap() {
  const canvas = $("map");
  canvas.dataset.ready = "";
  try {
    const params = { ...diskParams(), plane: $("plane").value, n: $("n").value,
                     ymax: $("ymax").value };
    state.map = await api("/api/map", params);
    showError("");
    drawMap();
  } catch (err) {
    showError(err.message);
  }
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

function fmt(v) {
  if (v === null || v === undefined) return "\u2013";
  if (typeof v === "number") return Number(v.toPrecision(6)).toString();
  return String(v);
}

function showSteady() {
  const box = $("steady"), grid = $("numbers"), reason = $("reason"), s = state.steady;
  grid.innerHTML = "";
  reason.hidden = true;
  if (!s) { box.dataset.exists = ""; return; }
  box.dataset.exists = s.exists ? "true" : "false";
  box.dataset.theta0 = String(state.selected.theta0);
  box.dataset.name = state.selected.name;
  box.dataset.value = String(state.selected.value);
  if (!s.exists) {
    reason.hidden = false;
    reason.textContent = "No steady motion: " + s.reason;
    return;
  }
  const add = (label, text) => {
    const l = document.createElement("span"), v = document.createElement("span");
    l.className = "label"; l.textContent = label; v.textContent = text;
    grid.append(l, v);
    return v;
  };
  for (const [key, label, numeric] of FIELDS) {
    const v = s[key], cell = add(label, fmt(v));
    cell.dataset.field = key;
    cell.dataset.value = v === null ? "" : String(v);   // full precision (shortest round trip)
    if (!numeric) cell.dataset.kind = "text";
  }
  if (s.si) {  // a disk with a physical size: SI beside the paper's units
    for (const [label, v] of Object.entries(s.si)) {
      const cell = add(label, fmt(v));
      cell.dataset.field = "si:" + label;
      cell.dataset.value = v === null ? "" : String(v);
    }
  }
  const rolls = s.mu_required <= mu();
  const cell = add(`Coulomb ground, \u03bc = ${mu().toFixed(2)}`, rolls ? "rolls" : "slides at once");
  cell.className = rolls ? "yes" : "no";
  cell.id = "rolls";
}

async function select(theta0, name, value) {
  state.selected = { theta0, name, value };
  drawMap();
  try {
    state.steady = await api("/api/steady", { ...diskParams(), theta0, [name]: value });
    showError("");
  } catch (err) {
    state.steady = null;
    showError(err.message);
  }
  showSteady();
  if (state.steady && state.steady.exists) await simulate();
  else clearView(state.steady ? "no steady motion here, nothing to simulate" : "");
}

// ------------------------------------------------------------------ simulation
async function simulate() {
  const sel = state.selected;
  if (!sel) return;
  const view = $("view");
  view.dataset.frames = "";
  $("sim-status").textContent = "simulating\u2026";
  try {
    state.traj = await api("/api/simulate", {
      ...diskParams(), theta0: sel.theta0, [sel.name]: sel.value,
      kick: $("kick").value, t_end: $("t_end").value, points: 1200 });
  } catch (err) {
    clearView(err.message);
    return;
  }
  const tr = state.traj;
  state.frame = 0;
  $("time").max = String(tr.t.length - 1);
  $("time").value = "0";
  $("time").disabled = false;
  $("play").disabled = false;
  $("resimulate").disabled = false;
  $("sim-status").textContent =
    tr.message;
  view.dataset.frames = String(tr.t.length);
  view.dataset.status = tr.status;
  setPlaying(true);
  drawView();
}

function clearView(message) {
  state.traj = null;
  setPlaying(false);
  $("play").disabled = true;
  $("time").disabled = true;
  $("resimulate").disabled = !(state.steady && state.steady.exists);
  $("sim-status").textContent = message || "";
  $("view").dataset.frames = "";
  drawView();
}

// --------------------------------------------------------------------- 3D view
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                         a[0] * b[1] - a[1] * b[0]];
const norm = (a) => { const l = Math.hypot(a[0], a[1], a[2]) || 1; return [a[0] / l, a[1] / l, a[2] / l]; };
const LIGHT = norm([0.3, -0.4, 0.9]);

function camera(target) {
  const { az, el, dist } = state.cam;
  const pos = [target[0] + dist * Math.cos(el) * Math.cos(az),
               target[1] + dist * Math.cos(el) * Math.sin(az), target[2] + dist * Math.sin(el)];
  const f = norm(sub(target, pos)), r = norm(cross(f, [0, 0, 1])), u = cross(r, f);
  const canvas = $("view"), focal = 0.9 * Math.min(canvas.width, canvas.height);
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

function drawView() {
  const canvas = $("view"), ctx = canvas.getContext("2d"), tr = state.traj;
  ctx.fillStyle = "#eef1f5"; ctx.fillRect(0, 0, canvas.width, canvas.height);
  if (!tr) {
    ctx.fillStyle = "#888"; ctx.font = "14px system-ui, sans-serif"; ctx.textAlign = "center";
    ctx.fillText("click a steady motion on the map", canvas.width / 2, canvas.height / 2);
    return;
  }
  const k = Math.min(state.frame, tr.t.length - 1), h = tr.h;
  const C = [tr.X_C[k], tr.Y_C[k], tr.Z_C[k]];
  const whole = pathTarget(tr);
  const target = $("follow").checked ? [C[0], C[1], 0.3] : whole.centre;
  const cam = camera(target);
  // ground grid, spacing 1 (the radius), around the target
  const g0x = Math.round(target[0]), g0y = Math.round(target[1]), L = 8;
  ctx.lineWidth = 1; ctx.strokeStyle = "#cfd6df";
  for (let i = -L; i <= L; i++) {
    polyline(ctx, cam, [[g0x + i, g0y - L, 0], [g0x + i, g0y + L, 0]], "#cfd6df", 1);
    polyline(ctx, cam, [[g0x - L, g0y + i, 0], [g0x + L, g0y + i, 0]], "#cfd6df", 1);
  }
  // paths up to now: contact point P (red) and centre C (blue)
  const P = [], Cs = [];
  for (let i = 0; i <= k; i++) {
    P.push([tr.X_P[i], tr.Y_P[i], 0]);
    Cs.push([tr.X_C[i], tr.Y_C[i], tr.Z_C[i]]);
  }
  polyline(ctx, cam, P, "#c0392b", 1.6);
  polyline(ctx, cam, Cs, "rgba(41, 98, 255, 0.7)", 1.2);
  // the disk: a cylinder of radius 1 and thickness 2h about C along the axis eta;
  // only the faces turned to the camera are drawn (a convex body needs no sorting)
  const eta = vec(tr.axis, k), e1 = vec(tr.e1, k), e2 = vec(tr.e2, k), N = 48;
  const rim = (side, a) => {
    const c = Math.cos(a), s = Math.sin(a);
    return [C[0] + side * h * eta[0] + c * e1[0] + s * e2[0],
            C[1] + side * h * eta[1] + c * e1[1] + s * e2[1],
            C[2] + side * h * eta[2] + c * e1[2] + s * e2[2]];
  };
  const facing = (point, normal) => dot(normal, sub(cam.pos, point)) > 0;
  const fill = (pts, color) => {
    const q = pts.map((p) => cam.project(p));
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
    polyline(ctx, cam, [centre, rim(side, 0)], "#b03030", 2.5);   // turns with phi
  }
  // contact point
  const q = cam.project([tr.X_P[k], tr.Y_P[k], 0]);
  if (q) { ctx.fillStyle = "#c0392b"; ctx.beginPath(); ctx.arc(q[0], q[1], 4, 0, 2 * Math.PI); ctx.fill(); }
  $("time-value").textContent =
    `t = ${tr.t[k].toFixed(2)}  \u03b8 = ${tr.theta[k].toFixed(4)}`;
}

// ------------------------------------------------------------------ playback
let lastTick = null;
function setPlaying(on) {
  state.playing = on && !!state.traj;
  $("play").innerHTML = state.playing ? "&#10074;&#10074; pause" : "&#9654; play";
  lastTick = null;
  if (state.playing) requestAnimationFrame(tick);
}

function tick(now) {
  const tr = state.traj;
  if (!state.playing || !tr) return;
  if (lastTick !== null) {
    // about 6 time units a second, whatever the number of stored points
    const dt = (now - lastTick) / 1000, span = tr.t[tr.t.length - 1] || 1;
    const step = Math.max(1, Math.round(dt * 6 / span * (tr.t.length - 1)));
    state.frame = (state.frame + step) % tr.t.length;
    $("time").value = String(state.frame);
    drawView();
  }
  lastTick = now;
  requestAnimationFrame(tick);
}

// ------------------------------------------------------------------ wiring
function wire() {
  const params = new URLSearchParams(location.search);
  if (params.get("h")) $("h").value = params.get("h");
  if (params.get("ground")) $("ground").value = params.get("ground");
  if (params.get("plane")) $("plane").value = params.get("plane");
  $("ymax").value = String(YMAX_DEFAULT[$("plane").value]);

  for (const id of ["ground", "h", "n", "ymax"]) $(id).addEventListener("change", () => {
    loadMap();
    if (state.selected) select(state.selected.theta0, state.selected.name, state.selected.value);
  });
  $("plane").addEventListener("change", () => {
    $("ymax").value = String(YMAX_DEFAULT[$("plane").value]);
    loadMap();
  });
  $("mu").addEventListener("input", () => {
    $("mu-value").textContent = mu().toFixed(2);
    drawMap();
    if (state.steady) showSteady();
  });
  $("map").addEventListener("click", (ev) => {
    if (!state.map) return;
    const canvas = $("map"), rect = canvas.getBoundingClientRect(), box = plotBox(canvas);
    const px = (ev.clientX - rect.left - canvas.clientLeft) * canvas.width / canvas.clientWidth;
    const py = (ev.clientY - rect.top - canvas.clientTop) * canvas.height / canvas.clientHeight;
    if (px < box.x0 || px > box.x0 + box.w || py < box.y0 || py > box.y0 + box.h) return;
    const [theta0, y] = fromPixel(box, px, py);
    select(theta0, state.map.y.name, y);
  });
  $("play").addEventListener("click", () => setPlaying(!state.playing));
  $("time").addEventListener("input", () => {
    setPlaying(false);
    state.frame = parseInt($("time").value, 10);
    drawView();
  });
  $("follow").addEventListener("change", drawView);
  $("resimulate").addEventListener("click", simulate);
  for (const id of ["kick", "t_end"]) $(id).addEventListener("change", () => {
    if (state.steady && state.steady.exists) simulate();
  });
  // rotate by dragging, zoom with the wheel
  const view = $("view");
  let drag = null;
  view.addEventListener("pointerdown", (ev) => { drag = [ev.clientX, ev.clientY]; view.setPointerCapture(ev.pointerId); });
  view.addEventListener("pointerup", () => { drag = null; });
  view.addEventListener("pointermove", (ev) => {
    if (!drag) return;
    state.cam.az -= (ev.clientX - drag[0]) * 0.01;
    state.cam.el = Math.min(1.5, Math.max(0.05, state.cam.el + (ev.clientY - drag[1]) * 0.01));
    drag = [ev.clientX, ev.clientY];
    drawView();
  });
  view.addEventListener("wheel", (ev) => {
    ev.preventDefault();
    state.cam.dist = Math.min(200, Math.max(2, state.cam.dist * Math.exp(ev.deltaY * 0.001)));
    drawView();
  }, { passive: false });
  drawView();
  loadMap();
}

wire();
