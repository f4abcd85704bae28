// The hidden-surfaces page: scene, method and orbit -> image, report and the method's figure.
"use strict";

function request() {
  const value = (id) => document.getElementById(id).value;
  const [width, height] = value("size").split("x").map(Number);
  return {
    scene: value("scene"), method: value("method"), shading: value("shading"),
    style: value("style"), azimuth: Number(value("azimuth")),
    elevation: Number(value("elevation")), width, height,
  };
}

const refresh = serialized(async () => {
  const asked = request();
  const answer = await api("hidden-surfaces", asked);
  if (!answer) return;
  const image = document.getElementById("image");
  image.src = answer.image;
  const zoom = answer.width <= 320 ? 2 : 1; // small pictures shown with their pixels doubled
  image.width = answer.width * zoom;
  image.height = answer.height * zoom;
  document.getElementById("caption").textContent =
    `${asked.scene} by ${asked.method}, ${asked.shading} shading, ${answer.width} × ${answer.height}`;
  const figureBox = document.getElementById("figure-box");
  figureBox.hidden = !answer.figure;
  if (answer.figure) document.getElementById("figure").src = answer.figure;
  showReport(answer.report);
});

function showReport(report) {
  const box = document.getElementById("report");
  box.replaceChildren();
  const summary = table(`what ${report.method} did`, ["", ""], report.summary);
  summary.id = "summary";
  box.appendChild(summary);
  for (const note of report.notes) box.appendChild(element("p", { class: "small" }, note));
  for (const t of report.tables) box.appendChild(table(t.title, t.columns, t.rows));
}

// Dragging the picture orbits the camera: a pixel of motion is half a degree.
function orbitByDragging(image) {
  let start = null;
  image.addEventListener("pointerdown", (event) => {
    event.preventDefault();
    start = { x: event.clientX, y: event.clientY,
              azimuth: Number(document.getElementById("azimuth").value),
              elevation: Number(document.getElementById("elevation").value) };
    image.setPointerCapture(event.pointerId);
  });
  image.addEventListener("pointerup", () => { start = null; });
  image.addEventListener("pointermove", (event) => {
    if (!start) return;
    const set = (id, value) => {
      const slider = document.getElementById(id);
      slider.value = value;
      slider.dispatchEvent(new Event("input"));
    };
    set("azimuth", start.azimuth - (event.clientX - start.x) / 2);
    set("elevation", start.elevation + (event.clientY - start.y) / 2);
  });
}

document.addEventListener("DOMContentLoaded", async () => {
  await fillChoices();
  for (const control of document.querySelectorAll("#options select, #options input")) {
    control.addEventListener(control.tagName === "SELECT" ? "change" : "input", refresh);
  }
  orbitByDragging(document.getElementById("image"));
  refresh();
});
