// rollingdisk explore: the page's script, an ES module.  It asks the server and wires the
// page's controls; the drawing (the map, the numbers, the 3D view, its playback) is the
// view module view.js, which the notebook widget draws with too.  No physics here: every
// number comes from /api/map, /api/steady and /api/simulate (the rollingdisk library);
// nothing is loaded from the network.
import * as view from "./view.js";

const $ = (id) => document.getElementById(id);
const YMAX_DEFAULT = { "theta0-omega30": 3, "theta0-Omega0": 3, "theta0-r_C": 2 };

const state = {
  map: null,        // the /api/map payload
  selected: null,   // {theta0, name, value}
  steady: null,     // the /api/steady payload
  traj: null,       // the /api/simulate payload
  cam: view.newCamera(),
};
const player = view.playback(() => state.traj, (frame) => {
  $("time").value = String(frame);
  drawView();
});

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
function mu() { return parseFloat($("mu").value); }

function showMap() {
  const canvas = $("map"), m = state.map, sel = state.selected, muNow = mu();
  const counts = view.drawMap(canvas, m, muNow,
                              m && sel && sel.name === m.y.name ? [sel.theta0, sel.value] : null);
  if (!counts) return;
  const { rolls, exist } = counts;
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
    showMap();
  } catch (err) {
    showError(err.message);
  }
}

// -------------------------------------------------------------- steady motion
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
  view.showNumbers(grid, s);
  const rolls = s.mu_required <= mu();
  const cell = view.addNumber(grid, `Coulomb ground, \u03bc = ${mu().toFixed(2)}`,
                              rolls ? "rolls" : "slides at once");
  cell.className = rolls ? "yes" : "no";
  cell.id = "rolls";
}

async function select(theta0, name, value) {
  state.selected = { theta0, name, value };
  showMap();
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
  const canvas = $("view");
  canvas.dataset.frames = "";
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
  player.frame = 0;
  $("time").max = String(tr.t.length - 1);
  $("time").value = "0";
  $("time").disabled = false;
  $("play").disabled = false;
  $("resimulate").disabled = false;
  $("sim-status").textContent =
    tr.message;
  canvas.dataset.frames = String(tr.t.length);
  canvas.dataset.status = tr.status;
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
function drawView() {
  const tr = state.traj;
  const k = view.drawScene($("view"), tr, player.frame, state.cam, $("follow").checked,
                           "click a steady motion on the map");
  if (k < 0) return;
  $("time-value").textContent =
    `t = ${tr.t[k].toFixed(2)}  \u03b8 = ${tr.theta[k].toFixed(4)}`;
}

function setPlaying(on) {
  $("play").innerHTML = player.play(on) ? "&#10074;&#10074; pause" : "&#9654; play";
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
    showMap();
    if (state.steady) showSteady();
  });
  $("map").addEventListener("click", (ev) => {
    if (!state.map) return;
    const point = view.mapPoint($("map"), state.map, ev);
    if (point) select(point[0], state.map.y.name, point[1]);
  });
  $("play").addEventListener("click", () => setPlaying(!player.playing));
  $("time").addEventListener("input", () => {
    setPlaying(false);
    player.frame = parseInt($("time").value, 10);
    drawView();
  });
  $("follow").addEventListener("change", drawView);
  $("resimulate").addEventListener("click", simulate);
  for (const id of ["kick", "t_end"]) $(id).addEventListener("change", () => {
    if (state.steady && state.steady.exists) simulate();
  });
  view.orbit($("view"), state.cam, drawView);   // rotate by dragging, zoom with the wheel
  drawView();
  loadMap();
}

wire();
