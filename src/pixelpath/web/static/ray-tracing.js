// The ray-tracing page: render the scene, click a pixel, draw and list its tree of rays.
"use strict";

const WIDTH = 320;
const HEIGHT = 200;
const ZOOM = 2;
const COLOURS = { primary: "#1d232b", reflected: "#1f6feb", refracted: "#12b76a",
                  shadow: "#fdb022", blocked: "#d92d20" };
let picked = null;

function view() {
  return {
    scene: document.getElementById("scene").value,
    azimuth: Number(document.getElementById("azimuth").value),
    width: WIDTH, height: HEIGHT,
  };
}

const refresh = serialized(async () => {
  const answer = await api("hidden-surfaces", { ...view(), method: "raytrace" });
  if (!answer) return;
  const image = document.getElementById("image");
  image.src = answer.image;
  image.width = WIDTH * ZOOM;
  image.height = HEIGHT * ZOOM;
  if (picked) await trace();
});

async function trace() {
  const maxDepth = Number(document.getElementById("max-depth").value);
  const answer = await api("ray-tree", { ...view(), pixel: picked, max_depth: maxDepth });
  if (!answer) return;
  document.getElementById("caption").textContent =
    `pixel (${answer.pixel.join(", ")}): ${answer.rays} ray(s), colour ${fmtVector(answer.rgb)}`;
  drawRays(answer);
  const box = document.getElementById("tree");
  box.replaceChildren();
  const list = box.appendChild(element("ul", { class: "tree", id: "tree-root" }));
  list.appendChild(nodeItem(answer.tree));
  document.getElementById("tree-text").textContent = answer.text;
}

function drawRays(answer) {
  const overlay = document.getElementById("rays");
  overlay.replaceChildren();
  overlay.setAttribute("width", WIDTH * ZOOM);
  overlay.setAttribute("height", HEIGHT * ZOOM);
  overlay.setAttribute("viewBox", `0 0 ${WIDTH} ${HEIGHT}`);
  for (const segment of answer.segments) {
    if (!segment.image) continue;
    const [[x1, y1], [x2, y2]] = segment.image;
    const kind = segment.kind === "shadow" && segment.blocked ? "blocked" : segment.kind;
    overlay.appendChild(svg("line", {
      x1, y1, x2, y2, stroke: COLOURS[kind], "stroke-width": 1.2,
      "stroke-dasharray": segment.kind === "shadow" ? "3 2" : "none", class: "ray " + kind,
    }));
  }
  const [x, y] = picked;
  overlay.appendChild(svg("circle", { cx: x + 0.5, cy: y + 0.5, r: 4, fill: "none",
                                      stroke: "#fff", "stroke-width": 1.5 }));
}

function nodeItem(node) {
  const item = element("li");
  const title = `${node.kind} ray (depth ${node.depth}, weight ${fmt(node.weight)})`;
  item.appendChild(element("span", { class: "kind" }, title));
  const rows = [
    ["origin", fmtVector(node.origin)], ["direction", fmtVector(node.direction)],
  ];
  if (node.hit) {
    rows.push(["hit", `object ${node.object} at t = ${fmt(node.t)}`],
              ["point", fmtVector(node.point)], ["normal", fmtVector(node.normal)]);
    if (node.quadratic) {
      const q = node.quadratic;
      rows.push(["sphere: a t² + b t + c = 0",
                 `a = ${fmt(q.a)}, b = ${fmt(q.b)}, c = ${fmt(q.c)}, b² − 4ac = ${fmt(q.discriminant)}, ` +
                 `t = ${q.roots.map((r) => fmt(r)).join(", ") || "none"}`]);
    }
    rows.push(["ambient", fmtVector(node.ambient)]);
    for (const light of node.lights) {
      const shadow = !light.tested ? "light behind the surface"
        : light.let_through < 1 ? `blocked by object ${light.blocker}` : "unobstructed";
      rows.push([`light ${light.light}`,
                 `N·L = ${fmt(light.n_dot_l)}, ${shadow}; diffuse ${fmtVector(light.diffuse)}, ` +
                 `specular ${fmtVector(light.specular)}`]);
    }
    rows.push(["I local", fmtVector(node.local)],
              ["kr, kt", `${fmt(node.kr)}, ${fmt(node.kt)}` +
                         (node.total_internal_reflection ? " (total internal reflection)" : "")],
              ["I = I local + kr I_R + kt I_T", fmtVector(node.color)]);
  } else {
    rows.push(["hit", "nothing: the background"]);
  }
  item.appendChild(table("", ["", ""], rows));
  const children = ["reflected", "refracted"].filter((kind) => node[kind]);
  if (children.length) {
    const list = item.appendChild(element("ul", { class: "tree" }));
    for (const kind of children) list.appendChild(nodeItem(node[kind]));
  }
  return item;
}

function pick(event) {
  picked = clickedPixel(event, WIDTH, HEIGHT);
  trace();
}

document.addEventListener("DOMContentLoaded", async () => {
  await fillChoices();
  document.getElementById("scene").addEventListener("change", refresh);
  document.getElementById("azimuth").addEventListener("input", refresh);
  document.getElementById("max-depth").addEventListener("input", () => { if (picked) trace(); });
  document.getElementById("image").addEventListener("click", pick);
  refresh();
});
