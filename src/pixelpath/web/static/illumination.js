// The illumination page: sliders -> three shaded balls; a click -> the Phong terms there.
"use strict";

const SIZE = 240;
const SHADINGS = ["flat", "gouraud", "phong"];
let picked = null; // [x, y] of the clicked pixel

function inputs() {
  const value = (id) => Number(document.getElementById(id).value);
  const hex = document.getElementById("colour").value;
  const colour = [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16) / 255);
  return {
    ka: value("ka"), kd: value("kd"), ks: value("ks"), n: value("n"),
    ia: value("ia"), il: value("il"), light: [value("lx"), value("ly"), value("lz")],
    color: colour, width: SIZE, height: SIZE,
  };
}

const refresh = serialized(async () => {
  const answer = await api("illumination", inputs());
  if (!answer) return;
  for (const shading of SHADINGS) {
    document.getElementById("img-" + shading).src = answer.images[shading];
  }
  if (picked) await explainPoint();
});

async function explainPoint() {
  const answer = await api("illumination/point", { ...inputs(), pixel: picked });
  if (!answer) return;
  markPoint();
  const box = document.getElementById("point");
  box.replaceChildren();
  if (!answer.hit) {
    box.appendChild(element("p", {}, `pixel (${picked.join(", ")}) misses the ball`));
    return;
  }
  const p = inputs();
  const t = answer.terms;
  const rows = [
    ["ambient", "ka·Ia", `${fmt(p.ka)} × ${fmt(p.ia)}`, t.ambient],
    ["diffuse", "kd·IL·max(0, N·L)", `${fmt(p.kd)} × ${fmt(p.il)} × ${fmt(Math.max(0, answer.n_dot_l))}`, t.diffuse],
    ["specular", "ks·IL·max(0, R·V)^n",
     `${fmt(p.ks)} × ${fmt(p.il)} × ${fmt(Math.max(0, answer.r_dot_v))}^${fmt(p.n)}`, t.specular],
    ["total", "", "", t.total],
    ["clamped to [0, 1]", "", "", t.clamped],
  ];
  const terms = table(`the terms at pixel (${answer.pixel.join(", ")})`, ["term", "formula", "values", "I"], rows);
  terms.id = "terms";
  box.appendChild(terms);
  box.appendChild(table("geometry (unit vectors; N on the exact sphere)", ["", "value"], [
    ["point P", fmtVector(answer.point)], ["normal N", fmtVector(answer.normal)],
    ["to the light L", fmtVector(answer.to_light)], ["to the eye V", fmtVector(answer.to_eye)],
    ["reflection R = 2(N·L)N − L", fmtVector(answer.reflected)],
    ["N·L", answer.n_dot_l], ["R·V", answer.r_dot_v],
  ]));
  const swatch = element("span", { class: "swatch" });
  swatch.style.background = `rgb(${answer.rgb.map((c) => Math.round(c * 255)).join(",")})`;
  const line = box.appendChild(element("p", {},
    `displayed: (ambient + diffuse) × colour + specular = ${fmtVector(answer.rgb)} `));
  line.appendChild(swatch);
}

function markPoint() {
  for (const shading of SHADINGS) {
    const stack = document.getElementById("img-" + shading).parentElement;
    stack.querySelector("svg.overlay")?.remove();
    const overlay = stack.appendChild(svg("svg", { class: "overlay", width: SIZE, height: SIZE,
                                                   viewBox: `0 0 ${SIZE} ${SIZE}` }));
    const [x, y] = picked;
    overlay.appendChild(svg("circle", { cx: x + 0.5, cy: y + 0.5, r: 6, fill: "none",
                                        stroke: "#fff", "stroke-width": 2 }));
    overlay.appendChild(svg("circle", { cx: x + 0.5, cy: y + 0.5, r: 7, fill: "none",
                                        stroke: "#1d232b", "stroke-width": 1 }));
  }
}

function pick(event) {
  picked = clickedPixel(event, SIZE, SIZE);
  explainPoint();
}

document.addEventListener("DOMContentLoaded", () => {
  for (const control of document.querySelectorAll("#sliders input")) {
    control.addEventListener("input", refresh);
  }
  for (const shading of SHADINGS) {
    document.getElementById("img-" + shading).addEventListener("click", pick);
  }
  refresh();
});
