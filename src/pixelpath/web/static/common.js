// Shared by every page of the playground: navigation, API calls, number formatting, clicks.
"use strict";

const PAGES = [
  ["/clipping", "Clipping"],
  ["/illumination", "Illumination"],
  ["/hidden-surfaces", "Hidden surfaces"],
  ["/ray-tracing", "Ray tracing"],
  ["/colour", "Colour"],
  ["/practice", "Practice"],
];

function buildNavigation() {
  const nav = document.getElementById("nav");
  if (!nav) return;
  const home = document.createElement("a");
  home.href = "/";
  home.textContent = "pixelpath playground";
  home.className = "home";
  nav.appendChild(home);
  for (const [path, title] of PAGES) {
    const link = document.createElement("a");
    link.href = path;
    link.textContent = title;
    if (window.location.pathname === path) link.className = "current";
    nav.appendChild(link);
  }
}

// POST a JSON body to the API; resolve to the answer, or show the error and resolve to null.
async function api(path, body) {
  const status = document.getElementById("status");
  const started = performance.now();
  if (status) status.textContent = "working…";
  let response;
  try {
    response = await fetch("/api/" + path, {
      method: body === undefined ? "GET" : "POST",
      headers: body === undefined ? {} : { "Content-Type": "application/json" },
      body: body === undefined ? undefined : JSON.stringify(body),
    });
  } catch (error) {
    showError("the playground does not answer (" + error.message + ")");
    return null;
  }
  const answer = await response.json().catch(() => ({ error: "answer is not JSON" }));
  if (!response.ok) {
    showError(answer.error || response.statusText);
    if (status) status.textContent = "";
    return null;
  }
  showError("");
  if (status) status.textContent = `${Math.round(performance.now() - started)} ms`;
  return answer;
}

function showError(message) {
  const box = document.getElementById("error");
  if (!box) return;
  box.textContent = message;
  box.hidden = !message;
}

// Run `work` (an async function) now, or once more after the current run when called again
// meanwhile: dragging sends one request at a time and always ends with the latest state.
function serialized(work) {
  let running = false;
  let again = false;
  return async function run() {
    if (running) {
      again = true;
      return;
    }
    running = true;
    try {
      do {
        again = false;
        await work();
      } while (again);
    } finally {
      running = false;
    }
  };
}

function fmt(value, digits = 4) {
  if (value === null || value === undefined) return "—";
  if (typeof value !== "number") return String(value);
  if (Number.isInteger(value)) return Math.abs(value) >= 10000 ? value.toLocaleString("en") : String(value);
  if (Math.abs(value) < 1e-12) return "0";
  if (Math.abs(value) < 1e-3) return value.toPrecision(2);
  return String(Number(value.toFixed(digits)));
}

function fmtVector(values, digits = 4) {
  if (!values) return "—";
  return "(" + values.map((v) => fmt(v, digits)).join(", ") + ")";
}

function element(tag, attributes = {}, text = "") {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  if (text !== "") node.textContent = text;
  return node;
}

// A table with a caption, header cells and rows of cells (formatted with fmt).
function table(caption, columns, rows) {
  const result = element("table");
  if (caption) result.appendChild(element("caption", {}, caption));
  const head = result.appendChild(element("thead")).appendChild(element("tr"));
  for (const name of columns) head.appendChild(element("th", {}, name));
  const body = result.appendChild(element("tbody"));
  for (const row of rows) {
    const line = body.appendChild(element("tr"));
    for (const cell of row) line.appendChild(element("td", {}, fmt(cell)));
  }
  return result;
}

// Fill <select data-choices="key"> elements from the list `key` of an API listing: names, or
// {name, title} pairs (shown by title).
async function fillChoices(listing = "scenes") {
  const names = await api(listing);
  if (!names) return null;
  for (const select of document.querySelectorAll("select[data-choices]")) {
    for (const choice of names[select.dataset.choices]) {
      const { name, title } = typeof choice === "string" ? { name: choice, title: choice } : choice;
      select.appendChild(element("option", { value: name }, title));
    }
    if (select.dataset.default) select.value = select.dataset.default;
  }
  return names;
}

// Show each range input's value in the <output> that follows it.
function showSliderValues() {
  for (const slider of document.querySelectorAll("input[type=range]")) {
    const output = slider.parentElement.querySelector("output");
    if (!output) continue;
    const update = () => { output.textContent = slider.value; };
    slider.addEventListener("input", update);
    update();
  }
}

const SVG_NS = "http://www.w3.org/2000/svg";

function svg(tag, attributes = {}) {
  const node = document.createElementNS(SVG_NS, tag);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  return node;
}

document.addEventListener("DOMContentLoaded", () => {
  buildNavigation();
  showSliderValues();
});

// The image pixel (x, y) under a click on an image drawn at any size, clamped to the image.
function clickedPixel(event, width, height) {
  const box = event.target.getBoundingClientRect();
  const x = Math.floor(((event.clientX - box.left) / box.width) * width);
  const y = Math.floor(((event.clientY - box.top) / box.height) * height);
  return [Math.min(Math.max(x, 0), width - 1), Math.min(Math.max(y, 0), height - 1)];
}
