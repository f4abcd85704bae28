// The colour page: one colour in every model, with the steps of each conversion.
"use strict";

// `moveSliders`: false while the sliders are the source (an answer arriving late must not
// pull a slider back from where the user has moved it since).
async function convert(model, values, moveSliders = true) {
  const answer = await api("colour", { model, values });
  if (!answer) return;
  show(answer, moveSliders);
}

function show(answer, moveSliders) {
  document.getElementById("swatch").style.background = answer.hex;
  document.getElementById("picker").value = answer.hex;
  if (moveSliders) {
    answer.rgb.forEach((value, k) => {
      const slider = document.getElementById("rgb"[k]);
      slider.value = value;
      slider.parentElement.querySelector("output").textContent = fmt(value, 3);
    });
  }
  document.getElementById("summary").textContent =
    `${answer.model.toUpperCase()} ${fmtVector(answer.values)} = RGB ${fmtVector(answer.rgb)} = ${answer.hex}`;
  const steps = document.getElementById("to-rgb");
  steps.replaceChildren();
  if (answer.model !== "rgb") {
    for (const line of answer.to_rgb) steps.appendChild(element("li", {}, line));
  }
  const cards = document.getElementById("models");
  cards.replaceChildren();
  for (const [name, result] of Object.entries(answer.models)) {
    const card = cards.appendChild(element("div", { class: "panel", id: "model-" + name }));
    card.appendChild(element("h3", {}, `${name.toUpperCase()} ${fmtVector(result.values)}`));
    const list = card.appendChild(element("ol"));
    for (const line of result.steps) list.appendChild(element("li", {}, line));
  }
}

function fromSliders() {
  const value = (id) => Number(document.getElementById(id).value);
  return convert("rgb", [value("r"), value("g"), value("b")], false);
}

function fromPicker() {
  const hex = document.getElementById("picker").value;
  convert("rgb", [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16) / 255));
}

function fromText() {
  const text = document.getElementById("values").value;
  const values = text.split(/[\s,;]+/).filter(Boolean).map(Number);
  convert(document.getElementById("model").value, values);
}

document.addEventListener("DOMContentLoaded", async () => {
  await fillChoices();
  const throttled = serialized(async () => fromSliders());
  for (const id of ["r", "g", "b"]) document.getElementById(id).addEventListener("input", throttled);
  document.getElementById("picker").addEventListener("input", fromPicker);
  document.getElementById("convert").addEventListener("click", fromText);
  document.getElementById("values").addEventListener("keydown", (event) => {
    if (event.key === "Enter") fromText();
  });
  fromSliders();
});
