// The page of `lucent preview`: it listens to the server's events (server-sent events on
// /events) and draws what they carry. "image": a picture of the whole image (a coarse pass:
// one value per step x step block, drawn scaled up; or the finished image), "tile": a
// finished tile, "status": the state, figures and messages. Images are drawn in the order
// they came, each once decoded.
"use strict";
const token = new URLSearchParams(location.search).get("token") || "";
const canvas = document.getElementById("image");
const context = canvas.getContext("2d");
const el = (id) => document.getElementById(id);
let drawing = Promise.resolve();

function decoded(png) {
  const image = new Image();
  image.src = "data:image/png;base64," + png;
  return image.decode().then(() => image);
}

// Queues the drawing of one image event after those before it.
function queueDraw(data, draw) {
  const image = decoded(data.png);
  drawing = drawing.then(() => image).then(draw).catch(() => {});
}

function size(width, height) {
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
  }
  context.imageSmoothingEnabled = false;
}

function onPicture(event) {
  const data = JSON.parse(event.data);
  queueDraw(data, (image) => {
    size(data.imageWidth, data.imageHeight);
    context.drawImage(image, 0, 0, data.width * data.step, data.height * data.step);
    canvas.classList.remove("stale");
  });
}

function onTile(event) {
  const data = JSON.parse(event.data);
  queueDraw(data, (image) => context.drawImage(image, data.x, data.y));
}

function stateText(s) {
  const time = s.seconds.toFixed(2) + " s";
  switch (s.phase) {
    case "loading": return "render " + s.generation + ": loading the scene…";
    case "coarse": return "render " + s.generation + ": coarse pass, every " + s.step + "th pixel · " + time;
    case "tiles": return "render " + s.generation + ": tiles " + s.done + " / " + s.total + " · " + time;
    case "done": return "render " + s.generation + ": done in " + time;
    case "comparing": return "render " + s.generation + ": done; POV-Ray renders it…";
    case "cancelled": return "render " + s.generation + ": cancelled";
    case "invalid": return "render " + s.generation + ": the scene is invalid";
    default: return s.phase;
  }
}

// The sliders: a scene's numeric parameters (each set as -D name=value) and an animation's
// frame. Moving one renders again; at most one request is in flight, the latest value next.
let sliders = "";
const pending = new Map();
let sending = false;

function sendNext() {
  if (sending || pending.size === 0) return;
  const [name, value] = pending.entries().next().value;
  pending.delete(name);
  sending = true;
  const query = "?token=" + encodeURIComponent(token) + "&name=" + encodeURIComponent(name) +
    "&value=" + encodeURIComponent(value);
  fetch("/set" + query, { method: "POST" })
    .then((reply) => reply.text())
    .then((text) => { if (text) el("saved").textContent = text; })
    .catch(() => {})
    .finally(() => { sending = false; sendNext(); });
}

function slider(name, label, min, max, step, value) {
  const row = document.createElement("label");
  const title = document.createElement("span");
  title.textContent = label;
  const input = document.createElement("input");
  Object.assign(input, { type: "range", min, max, step, value });
  input.dataset.name = name;
  const shown = document.createElement("output");
  shown.textContent = value;
  input.addEventListener("input", () => {
    shown.textContent = input.value;
    pending.set(name, input.value);
    sendNext();
  });
  row.append(title, input, shown);
  return row;
}

// Rebuilt only when the scene's parameters or frames change, not while one is moved.
function showSliders(s) {
  const key = JSON.stringify([s.parameters.map((p) => [p.name, p.declared]), s.frames]);
  if (key === sliders) return;
  sliders = key;
  const controls = el("controls");
  controls.replaceChildren();
  for (const p of s.parameters) {
    const value = Number(p.value);
    let min = p.declared === 0 ? -1 : Math.min(0, 2 * p.declared);
    let max = p.declared === 0 ? 1 : Math.max(0, 2 * p.declared);
    min = Math.min(min, value);
    max = Math.max(max, value);
    controls.append(slider(p.name, p.name, min, max, (max - min) / 200, value));
  }
  if (s.frames > 0) controls.append(slider("frame", "frame", 1, s.frames, 1, s.frame));
  controls.append(slider("samples", "samples per pixel", 1, Math.max(16, s.samples), 1, s.samples));
}

function onStatus(event) {
  const s = JSON.parse(event.data);
  document.body.dataset.phase = s.phase;
  document.body.dataset.generation = s.generation;
  el("scene").textContent = s.scene;
  el("state").textContent = stateText(s);
  el("progress").value = s.phase === "done" ? 1 : s.total ? s.done / s.total : 0;
  el("stats").textContent = s.stats;
  // Once the scene is loaded: its frames and samples are known then.
  if (s.phase !== "loading" && s.phase !== "invalid") showSliders(s);
  el("whole").hidden = s.region === "";
  if (s.region && !dragStart) showRegion(...s.region.split(",").map(Number));
  else if (!dragStart) el("region").hidden = true;
  const messages = el("messages");
  messages.textContent = s.messages;
  messages.hidden = s.messages === "";
  messages.classList.toggle("error", s.phase === "invalid");
  // The last good image stays, dimmed, until the scene is valid again.
  if (s.phase === "invalid") drawing = drawing.then(() => canvas.classList.add("stale"));
}

// The button writes the last finished image where `lucent render` would (SCENE.png).
el("save").addEventListener("click", () => {
  fetch("/save?token=" + encodeURIComponent(token), { method: "POST" })
    .then((reply) => reply.text())
    .then((text) => { el("saved").textContent = text.trim(); })
    .catch(() => { el("saved").textContent = "not saved: no answer from lucent preview"; });
});

// The colour of the pixel under the pointer: the 8-bit sRGB value shown, and the linear
// value it encodes (the renderer's, to the byte's precision).
function linear(byte) {
  const c = byte / 255;
  return (c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4)).toFixed(3);
}
canvas.addEventListener("mousemove", (event) => {
  const r = canvas.getBoundingClientRect();
  const x = Math.floor((event.clientX - r.left) * canvas.width / r.width);
  const y = Math.floor((event.clientY - r.top) * canvas.height / r.height);
  if (x < 0 || y < 0 || x >= canvas.width || y >= canvas.height) return;
  const [red, green, blue] = context.getImageData(x, y, 1, 1).data;
  el("pixel").textContent = "pixel " + x + ", " + y + ": sRGB " + red + " " + green + " " + blue +
    " · linear " + linear(red) + " " + linear(green) + " " + linear(blue);
});

// A drag over the image renders only that rectangle, at full quality ("whole image" undoes
// it). The rectangle is shown in image pixels, scaled as the canvas is.
function imagePoint(event) {
  const r = canvas.getBoundingClientRect();
  const x = Math.floor((event.clientX - r.left) * canvas.width / r.width);
  const y = Math.floor((event.clientY - r.top) * canvas.height / r.height);
  return [Math.max(0, Math.min(canvas.width, x)), Math.max(0, Math.min(canvas.height, y))];
}

function showRegion(x0, y0, x1, y1) {
  const box = el("region");
  const scale = canvas.getBoundingClientRect().width / canvas.width;
  Object.assign(box.style, { left: x0 * scale + "px", top: y0 * scale + "px",
    width: (x1 - x0) * scale + "px", height: (y1 - y0) * scale + "px" });
  box.hidden = false;
}

function postRegion(region) {
  const query = "?token=" + encodeURIComponent(token) + (region ? "&region=" + region : "");
  fetch("/region" + query, { method: "POST" }).catch(() => {});
}

let dragStart = null;
canvas.addEventListener("mousedown", (event) => {
  dragStart = imagePoint(event);
  event.preventDefault();
});
window.addEventListener("mousemove", (event) => {
  if (!dragStart) return;
  const [x, y] = imagePoint(event);
  showRegion(Math.min(x, dragStart[0]), Math.min(y, dragStart[1]),
             Math.max(x, dragStart[0]), Math.max(y, dragStart[1]));
});
window.addEventListener("mouseup", (event) => {
  if (!dragStart) return;
  const [x, y] = imagePoint(event);
  const [x0, y0, x1, y1] = [Math.min(x, dragStart[0]), Math.min(y, dragStart[1]),
                            Math.max(x, dragStart[0]), Math.max(y, dragStart[1])];
  dragStart = null;
  if (x1 - x0 >= 2 && y1 - y0 >= 2) postRegion([x0, y0, x1, y1].join(","));
});
el("whole").addEventListener("click", () => postRegion(""));

// --compare: POV-Ray's render and the difference of the last finished render.
function onComparison(event) {
  const data = JSON.parse(event.data);
  el("comparison").hidden = false;
  el("comparison").dataset.generation = data.generation;
  el("povray").src = data.povray ? "data:image/png;base64," + data.povray : "";
  el("diff").src = data.diff ? "data:image/png;base64," + data.diff : "";
  el("report").textContent = data.error || data.report;
}

const events = new EventSource("/events?token=" + encodeURIComponent(token));
events.addEventListener("image", onPicture);
events.addEventListener("tile", onTile);
events.addEventListener("status", onStatus);
events.addEventListener("comparison", onComparison);
events.onerror = () => { el("state").textContent = "disconnected: is lucent preview still running?"; };
