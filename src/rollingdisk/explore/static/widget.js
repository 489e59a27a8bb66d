// The rollingdisk notebook view (anywidget's ES module contract: export default { render }).
// Python computes everything (rollingdisk.explore.widget); this module only draws:
//   map     -> the steady circles' map; a click sets `selected` = [theta0, omega30]
//   motion  -> the numbers of the selected steady motion (SI beside them for a real disk)
//   frames  -> the drawn disk along a run, played with a time slider
// No import, no request: the module is self-contained.

const COLORS = { "0": "#e9e9e9", "1": "#f4a582", "2": "#92c5de" };

function mapCanvas(model, el) {
  const canvas = document.createElement("canvas");
  canvas.width = 360; canvas.height = 300;
  canvas.className = "rd-map";
  canvas.style.cursor = "crosshair";
  el.appendChild(canvas);
  const pad = { l: 40, r: 8, t: 8, b: 30 };
  function geometry() {
    const m = model.get("map");
    if (!m || !m.x) return null;
    const xs = m.x.values, ys = m.y.values;
    return { m, xs, ys, w: canvas.width - pad.l - pad.r, h: canvas.height - pad.t - pad.b,
             x0: m.x.range[0], x1: m.x.range[1], y0: m.y.range[0], y1: m.y.range[1] };
  }
  function draw() {
    const g = geometry();
    const ctx = canvas.getContext("2d");
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    if (!g) return;
    const nx = g.xs.length, ny = g.ys.length;
    const cw = g.w / nx, ch = g.h / ny;
    for (let j = 0; j < ny; j++) {
      for (let i = 0; i < nx; i++) {
        ctx.fillStyle = COLORS[String(g.m.codes[j][i])] || "#ccc";
        ctx.fillRect(pad.l + i * cw, pad.t + (ny - 1 - j) * ch, cw + 0.5, ch + 0.5);
      }
    }
    ctx.fillStyle = "#222"; ctx.font = "11px sans-serif";
    ctx.fillText("theta0 [rad]", pad.l + g.w / 2 - 30, canvas.height - 6);
    ctx.save(); ctx.translate(12, pad.t + g.h / 2 + 30); ctx.rotate(-Math.PI / 2);
    ctx.fillText(g.m.y.name + " [sqrt(g/a)]", 0, 0); ctx.restore();
    const sel = model.get("selected");
    if (sel && sel.length === 2) {
      const px = pad.l + (sel[0] - g.x0) / (g.x1 - g.x0) * g.w;
      const py = pad.t + (1 - (sel[1] - g.y0) / (g.y1 - g.y0)) * g.h;
      ctx.strokeStyle = "#000"; ctx.beginPath(); ctx.arc(px, py, 5, 0, 2 * Math.PI);
      ctx.stroke();
    }
  }
  canvas.addEventListener("click", (ev) => {
    const g = geometry();
    if (!g) return;
    const r = canvas.getBoundingClientRect();
    const fx = (ev.clientX - r.left) * (canvas.width / r.width);
    const fy = (ev.clientY - r.top) * (canvas.height / r.height);
    const theta0 = g.x0 + (fx - pad.l) / g.w * (g.x1 - g.x0);
    const y = g.y0 + (1 - (fy - pad.t) / g.h) * (g.y1 - g.y0);
    if (theta0 <= g.x0 || theta0 >= g.x1 || y < g.y0 || y > g.y1) return;
    model.set("selected", [theta0, y]);
    model.save_changes();
    draw();
  });
  model.on("change:map", draw);
  model.on("change:selected", draw);
  draw();
  return canvas;
}

function numbersPanel(model, el) {
  const div = document.createElement("div");
  div.className = "rd-numbers";
  div.style.font = "12px monospace";
  div.style.whiteSpace = "pre";
  el.appendChild(div);
  function fmt(v) {
    return typeof v === "number" ? (Math.abs(v) < 1e-3 || Math.abs(v) >= 1e5
      ? v.toExponential(4) : v.toPrecision(6)) : String(v);
  }
  function draw() {
    const m = model.get("motion");
    if (!m || Object.keys(m).length === 0) { div.textContent = "click the map"; return; }
    if (!m.exists) { div.textContent = "no steady motion: " + m.reason; return; }
    const keys = ["theta0", "Omega0", "omega20", "omega30", "r_C", "varpi2", "stable",
                  "period", "mu_required"];
    let lines = keys.filter((k) => k in m).map((k) => k.padEnd(12) + fmt(m[k]));
    if (m.si) {
      lines.push("", "SI:");
      for (const [k, v] of Object.entries(m.si)) lines.push("  " + k.padEnd(18) + fmt(v));
    }
    div.textContent = lines.join("\n");
  }
  model.on("change:motion", draw);
  draw();
  return div;
}

function player(model, el) {
  const canvas = document.createElement("canvas");
  canvas.width = 360; canvas.height = 300;
  canvas.className = "rd-3d";
  const slider = document.createElement("input");
  slider.type = "range"; slider.min = 0; slider.max = 0; slider.value = 0;
  slider.style.width = "360px";
  const label = document.createElement("div");
  label.style.font = "11px sans-serif";
  el.appendChild(canvas); el.appendChild(slider); el.appendChild(label);
  const az = -Math.PI / 3, el3 = 0.5;
  function project(p, c, s) {  // orthographic view, azimuth az, elevation el3
    const x = p[0] - c[0], y = p[1] - c[1], z = p[2];
    const u = x * Math.cos(az) - y * Math.sin(az);
    const v = (x * Math.sin(az) + y * Math.cos(az)) * Math.sin(el3) + z * Math.cos(el3);
    return [canvas.width / 2 + s * u, canvas.height * 0.75 - s * v];
  }
  function draw() {
    const f = model.get("frames");
    const ctx = canvas.getContext("2d");
    ctx.fillStyle = "#fafafa"; ctx.fillRect(0, 0, canvas.width, canvas.height);
    if (!f || !f.rims || f.rims.length === 0) { label.textContent = ""; return; }
    slider.max = f.rims.length - 1;
    const i = Math.min(Number(slider.value), f.rims.length - 1);
    const rims = f.rims[i], P = f.contact[i];
    const c = [P[0], P[1], 0];
    const s = 70;
    ctx.strokeStyle = "#bbb"; ctx.beginPath();  // the plane's grid around P
    for (let k = -3; k <= 3; k++) {
      let a = project([c[0] + k, c[1] - 3, 0], c, s), b = project([c[0] + k, c[1] + 3, 0], c, s);
      ctx.moveTo(a[0], a[1]); ctx.lineTo(b[0], b[1]);
      a = project([c[0] - 3, c[1] + k, 0], c, s); b = project([c[0] + 3, c[1] + k, 0], c, s);
      ctx.moveTo(a[0], a[1]); ctx.lineTo(b[0], b[1]);
    }
    ctx.stroke();
    rims.forEach((rim, r) => {
      ctx.beginPath();
      rim.forEach((p, k) => {
        const q = project(p, c, s);
        if (k === 0) ctx.moveTo(q[0], q[1]); else ctx.lineTo(q[0], q[1]);
      });
      ctx.fillStyle = r === 0 ? "rgba(74,127,176,0.55)" : "rgba(158,202,225,0.85)";
      ctx.fill(); ctx.strokeStyle = "#234"; ctx.stroke();
    });
    const q = project(P, c, s);
    ctx.fillStyle = "#d62728"; ctx.beginPath(); ctx.arc(q[0], q[1], 3, 0, 2 * Math.PI);
    ctx.fill();
    const d = model.get("disk") || {};
    const t = f.t[i];
    label.textContent = "t = " + t.toFixed(2) + " sqrt(a/g)" +
      (d.time_s ? "  (" + (t * d.time_s).toFixed(3) + " s)" : "");
  }
  slider.addEventListener("input", draw);
  model.on("change:frames", () => { slider.value = 0; draw(); });
  draw();
  return canvas;
}

function render({ model, el }) {
  el.classList.add("rollingdisk-view");
  const row = document.createElement("div");
  row.style.display = "flex"; row.style.flexWrap = "wrap"; row.style.gap = "12px";
  el.appendChild(row);
  const left = document.createElement("div");
  const right = document.createElement("div");
  row.appendChild(left); row.appendChild(right);
  const m = model.get("map");
  if (m && m.x) { mapCanvas(model, left); numbersPanel(model, left); }
  player(model, right);
}

export default { render };
