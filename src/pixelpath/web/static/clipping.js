// The clipping page: drag the polygons, ask the API to clip, draw the traces.
"use strict";

const VIEW = { x0: -1, y1: 11, scale: 40, width: 640, height: 480 };
const EXAMPLES = {
  notes: { subject: [[1, 1], [9, 1], [9, 7], [1, 7]], window: [[2, 2], [8, 2], [8, 6], [2, 6]] },
  concave: {
    subject: [[1, 1], [12, 1], [12, 9], [1, 9], [1, 6.5], [9, 6.5], [9, 3.5], [1, 3.5]],
    window: [[0, 0], [6, 0], [6, 10], [0, 10]],
  },
};
const X_PARTNER = [3, 2, 1, 0]; // the rectangle corner sharing each corner's x
const Y_PARTNER = [1, 0, 3, 2]; // ... and its y

const state = {
  subject: EXAMPLES.concave.subject.map((p) => p.slice()),
  window: EXAMPLES.concave.window.map((p) => p.slice()),
  answer: null,
  stage: 0,
  step: 0,
  dragging: null,
};

function toScreen([x, y]) {
  return [(x - VIEW.x0) * VIEW.scale, (VIEW.y1 - y) * VIEW.scale];
}

function toWorld(event) {
  const box = document.getElementById("plane").getBoundingClientRect();
  const sx = ((event.clientX - box.left) / box.width) * VIEW.width;
  const sy = ((event.clientY - box.top) / box.height) * VIEW.height;
  const snap = (v) => Math.round(v * 4) / 4; // quarter units keep the tables readable
  return [snap(sx / VIEW.scale + VIEW.x0), snap(VIEW.y1 - sy / VIEW.scale)];
}

function pointsAttribute(points) {
  return points.map((p) => toScreen(p).join(",")).join(" ");
}

function rectangle() {
  return document.getElementById("rect").checked;
}

function windowForRequest() {
  if (!rectangle()) return state.window;
  const xs = state.window.map((p) => p[0]);
  const ys = state.window.map((p) => p[1]);
  return [Math.min(...xs), Math.min(...ys), Math.max(...xs), Math.max(...ys)];
}

const refresh = serialized(async () => {
  const answer = await api("clip", { subject: state.subject, window: windowForRequest() });
  if (answer) state.answer = answer;
  draw();
  showTraces();
});

// ----- drawing ------------------------------------------------------------------------------

function draw() {
  const plane = document.getElementById("plane");
  plane.replaceChildren();
  drawGrid(plane);
  const windowPolygon = plane.appendChild(svg("polygon", {
    points: pointsAttribute(state.window), fill: "#1f6feb", "fill-opacity": 0.08,
    stroke: "#1f6feb", "stroke-width": 2,
  }));
  windowPolygon.id = "window";
  plane.appendChild(svg("polygon", {
    points: pointsAttribute(state.subject), fill: "none", stroke: "#98a2b3",
    "stroke-width": 2, "stroke-dasharray": "6 4",
  }));
  const sh = state.answer && state.answer.sutherland_hodgman;
  const wa = state.answer && state.answer.weiler_atherton;
  if (wa && wa.pieces && document.getElementById("show-wa").checked) {
    for (const piece of wa.pieces) {
      plane.appendChild(svg("polygon", {
        points: pointsAttribute(piece), fill: "#f79009", "fill-opacity": 0.35,
        stroke: "#f79009", "stroke-width": 2, class: "wa-piece",
      }));
    }
  }
  if (sh && sh.result && document.getElementById("show-sh").checked) {
    if (sh.result.length) {
      plane.appendChild(svg("polygon", {
        points: pointsAttribute(sh.result), fill: "#12b76a", "fill-opacity": 0.25,
        stroke: "#12b76a", "stroke-width": 3, class: "sh-result",
      }));
    }
  }
  if (sh && sh.stages) drawStep(plane, sh);
  if (sh && sh.bridges && document.getElementById("show-sh").checked) {
    for (const [a, b] of sh.bridges) drawSegment(plane, a, b, "#d92d20", 5, "bridge");
  }
  drawHandles(plane);
}

function drawGrid(plane) {
  for (let x = Math.ceil(VIEW.x0); x <= VIEW.x0 + VIEW.width / VIEW.scale; x++) {
    const [sx] = toScreen([x, 0]);
    plane.appendChild(svg("line", { x1: sx, y1: 0, x2: sx, y2: VIEW.height,
                                    stroke: x === 0 ? "#98a2b3" : "#eef0f3" }));
  }
  for (let y = Math.floor(VIEW.y1); y >= VIEW.y1 - VIEW.height / VIEW.scale; y--) {
    const [, sy] = toScreen([0, y]);
    plane.appendChild(svg("line", { x1: 0, y1: sy, x2: VIEW.width, y2: sy,
                                    stroke: y === 0 ? "#98a2b3" : "#eef0f3" }));
  }
}

function drawSegment(plane, a, b, colour, width, className) {
  const [x1, y1] = toScreen(a);
  const [x2, y2] = toScreen(b);
  return plane.appendChild(svg("line", { x1, y1, x2, y2, stroke: colour, "stroke-width": width,
                                         "stroke-linecap": "round", class: className }));
}

// The current boundary (extended across the plane), S -> E and what this step emits.
function drawStep(plane, sh) {
  const stage = sh.stages[state.stage];
  if (!stage) return;
  const [a, b] = boundaryLine(sh, state.stage);
  drawSegment(plane, a, b, "#1f6feb", 4, "boundary").setAttribute("stroke-opacity", 0.45);
  const step = stage.steps[state.step];
  if (!step) return;
  drawSegment(plane, step.s, step.e, "#1d232b", 3, "current-edge");
  for (const point of step.emitted) {
    const [cx, cy] = toScreen(point);
    plane.appendChild(svg("circle", { cx, cy, r: 7, fill: "#d92d20", class: "emitted" }));
  }
}

function boundaryLine(sh, index) {
  const far = 100;
  const name = sh.stages[index].boundary;
  const corners = sh.window;
  const xs = corners.map((p) => p[0]);
  const ys = corners.map((p) => p[1]);
  const sides = {
    left: [[Math.min(...xs), -far], [Math.min(...xs), far]],
    right: [[Math.max(...xs), -far], [Math.max(...xs), far]],
    bottom: [[-far, Math.min(...ys)], [far, Math.min(...ys)]],
    top: [[-far, Math.max(...ys)], [far, Math.max(...ys)]],
  };
  if (sides[name]) return sides[name];
  const a = corners[index];
  const b = corners[(index + 1) % corners.length];
  const d = [b[0] - a[0], b[1] - a[1]];
  return [[a[0] - far * d[0], a[1] - far * d[1]], [a[0] + far * d[0], a[1] + far * d[1]]];
}

function drawHandles(plane) {
  state.subject.forEach((point, k) => {
    const [cx, cy] = toScreen(point);
    const handle = plane.appendChild(svg("circle", {
      cx, cy, r: 8, fill: "#667085", stroke: "#fff", "stroke-width": 2, class: "handle subject",
      "data-index": k,
    }));
    handle.addEventListener("pointerdown", (event) => startDrag(event, "subject", k));
  });
  state.window.forEach((point, k) => {
    const [x, y] = toScreen(point);
    const handle = plane.appendChild(svg("rect", {
      x: x - 7, y: y - 7, width: 14, height: 14, fill: "#1f6feb", stroke: "#fff",
      "stroke-width": 2, class: "handle corner", "data-index": k,
    }));
    handle.addEventListener("pointerdown", (event) => startDrag(event, "window", k));
  });
}

// ----- dragging -----------------------------------------------------------------------------

function startDrag(event, which, index) {
  event.preventDefault();
  state.dragging = { which, index };
  document.getElementById("plane").setPointerCapture(event.pointerId);
}

function moveDrag(event) {
  if (!state.dragging) return;
  const [x, y] = toWorld(event);
  const { which, index } = state.dragging;
  if (which === "subject") {
    state.subject[index] = [x, y];
  } else {
    state.window[index] = [x, y];
    if (rectangle()) {
      state.window[X_PARTNER[index]][0] = x;
      state.window[Y_PARTNER[index]][1] = y;
    }
  }
  draw();
  refresh();
}

function endDrag() {
  state.dragging = null;
}

// ----- tables -------------------------------------------------------------------------------

function point(p) {
  return "(" + p.map((v) => fmt(v, 3)).join(", ") + ")";
}

function pointList(points) {
  return points.length ? points.map(point).join(" ") : "(empty)";
}

function showTraces() {
  const answer = state.answer;
  if (!answer) return;
  const sh = answer.sutherland_hodgman;
  const stages = document.getElementById("stages");
  stages.replaceChildren();
  const tableBox = document.getElementById("stage-table");
  tableBox.replaceChildren();
  document.getElementById("sh-error").textContent = sh.error
    ? "Sutherland-Hodgman: " + sh.error : "";
  if (sh.stages) {
    state.stage = Math.min(state.stage, sh.stages.length - 1);
    sh.stages.forEach((stage, k) => {
      const button = stages.appendChild(element("button", {}, stage.boundary));
      if (k === state.stage) button.className = "current";
      button.addEventListener("click", () => { state.stage = k; state.step = 0; draw(); showTraces(); });
    });
    const stage = sh.stages[state.stage];
    const slider = document.getElementById("step");
    slider.max = Math.max(stage.steps.length - 1, 0);
    state.step = Math.min(state.step, stage.steps.length - 1);
    slider.value = state.step;
    document.getElementById("step-label").textContent =
      `${state.step + 1} of ${stage.steps.length}`;
    tableBox.appendChild(element("p", { class: "small" }, "input: " + pointList(stage.input)));
    const rows = stage.steps.map((s) => [point(s.s), point(s.e), s.case,
                                         s.emitted.length ? pointList(s.emitted) : "nothing"]);
    const stepTable = table(`clip against the ${stage.boundary} boundary`,
                            ["S", "E", "case", "output"], rows);
    stepTable.id = "sh-table";
    const current = stepTable.tBodies[0].rows[state.step];
    if (current) current.className = "current";
    tableBox.appendChild(stepTable);
    tableBox.appendChild(element("p", { class: "small" }, "output: " + pointList(stage.output)));
    const bridges = sh.bridges.length
      ? ` — ${sh.bridges.length} zero-width bridge(s) along the window (red)` : "";
    document.getElementById("sh-result").textContent =
      "Clipped polygon: " + (sh.result.length ? pointList(sh.result) : "nothing is left") + bridges;
  } else {
    document.getElementById("sh-result").textContent = "";
  }
  const wa = answer.weiler_atherton;
  const waBox = document.getElementById("wa-table");
  waBox.replaceChildren();
  if (wa.error) {
    waBox.appendChild(element("p", { class: "small" }, "Weiler-Atherton: " + wa.error));
  } else {
    const rows = wa.steps.map((s) => [s.loop + 1, point(s.start), point(s.end), s.along,
                                      s.switch ? "switch" : ""]);
    const walk = table(`${wa.pieces.length} piece(s); the walk`,
                       ["piece", "from", "to", "along", ""], rows);
    walk.id = "wa-walk";
    waBox.appendChild(walk);
  }
  document.getElementById("traces").textContent =
    [sh.text || sh.error, wa.text || wa.error].join("\n\n");
}

// ----- set-up -------------------------------------------------------------------------------

function loadExample(name) {
  state.subject = EXAMPLES[name].subject.map((p) => p.slice());
  state.window = EXAMPLES[name].window.map((p) => p.slice());
  document.getElementById("rect").checked = true;
  state.stage = 0;
  state.step = 0;
  draw();
  refresh();
}

document.addEventListener("DOMContentLoaded", () => {
  const plane = document.getElementById("plane");
  plane.addEventListener("pointermove", moveDrag);
  plane.addEventListener("pointerup", endDrag);
  plane.addEventListener("pointercancel", endDrag);
  document.getElementById("step").addEventListener("input", (event) => {
    state.step = Number(event.target.value);
    draw();
    showTraces();
  });
  for (const id of ["show-sh", "show-wa"]) {
    document.getElementById(id).addEventListener("change", draw);
  }
  document.getElementById("rect").addEventListener("change", () => {
    if (rectangle()) {
      const [xmin, ymin, xmax, ymax] = windowForRequest();
      state.window = [[xmin, ymin], [xmax, ymin], [xmax, ymax], [xmin, ymax]];
    }
    draw();
    refresh();
  });
  document.getElementById("example-notes").addEventListener("click", () => loadExample("notes"));
  document.getElementById("example-concave").addEventListener("click", () => loadExample("concave"));
  document.getElementById("add-vertex").addEventListener("click", () => {
    const last = state.subject[state.subject.length - 1];
    const first = state.subject[0];
    state.subject.push([(last[0] + first[0]) / 2, (last[1] + first[1]) / 2]);
    draw();
    refresh();
  });
  document.getElementById("remove-vertex").addEventListener("click", () => {
    if (state.subject.length > 3) state.subject.pop();
    draw();
    refresh();
  });
  draw();
  refresh();
});
