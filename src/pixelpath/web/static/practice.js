// The practice page: a seeded exam question, the student's answer marked, the worked solution.
"use strict";

// How each kind of answer is typed (what pixelpath.exercises' Field.parse reads).
const TYPING = {
  number: "a number, or none",
  vector: "(x, y, z), or none",
  polygon: "(x1, y1) (x2, y2) …",
  polygons: "(x, y) (x, y) …; (x, y) …",
  sequence: "A, B, C in order",
  set: "A, B, C in any order",
  choice: "one label",
  grid: "rows of labels, space between rows",
};

let current = null; // the exercise shown: the API's answer to "exercise"
let marked = null; // the API's answer to the last check of it, which holds the solution

function showFigure(boxId, imageId, url) {
  document.getElementById(imageId).src = url || "";
  document.getElementById(boxId).hidden = !url;
}

async function newExercise() {
  const seed = document.getElementById("seed").value.trim();
  const request = {
    topic: document.getElementById("topic").value,
    difficulty: document.getElementById("difficulty").value,
  };
  // Digits go as a number; anything else as typed, for the API to refuse with its message.
  if (seed !== "") request.seed = /^\d+$/.test(seed) ? Number(seed) : seed;
  const exercise = await api("exercise", request);
  if (!exercise) return;
  current = exercise;
  marked = null;
  showQuestion(exercise);
  showFields(exercise.fields);
  showMarking(null);
  document.getElementById("solution-box").hidden = true;
}

function showQuestion(exercise) {
  document.getElementById("title").textContent =
    `${exercise.title} · seed ${exercise.seed} · ${exercise.difficulty}`;
  const question = document.getElementById("question");
  question.innerHTML = exercise.question; // HTML the API rendered from the library's Markdown
  // A question that shows its figure inline needs no second copy below it.
  showFigure("figure-box", "figure", question.querySelector("img.figure") ? null : exercise.figure);
  document.getElementById("marking").textContent = exercise.marking;
  document.getElementById("check").disabled = false;
}

function showFields(fields) {
  const answers = document.getElementById("answers");
  answers.replaceChildren();
  for (const field of fields) {
    const row = answers.appendChild(element("label", { id: "field-" + field.name }));
    row.appendChild(element("span", {}, `${field.name}: ${field.label}`));
    const input = row.appendChild(element("input", {
      type: "text", name: field.name, placeholder: TYPING[field.kind], autocomplete: "off",
    }));
    input.required = field.required;
    input.addEventListener("keydown", (event) => {
      if (event.key === "Enter") checkAnswer();
    });
    const need = field.required ? "required" : `optional (step ${field.step})`;
    row.appendChild(element("span", { class: field.required ? "need required" : "need" }, need));
    row.appendChild(element("output", { class: "mark" }));
  }
}

async function checkAnswer() {
  const values = {};
  // A blank box is an unanswered value; "none" is typed for a value that does not exist.
  for (const input of document.querySelectorAll("#answers input")) {
    if (input.value.trim() !== "") values[input.name] = input.value;
  }
  const { topic, seed, difficulty } = current;
  const answer = await api("exercise/check", { topic, seed, difficulty, values });
  if (!answer) return;
  marked = answer;
  showMarking(answer);
}

// Mark each answered (or required) field right or wrong; null clears the marking.
function showMarking(answer) {
  const marks = answer ? answer.marks : {};
  for (const row of document.querySelectorAll("#answers label")) {
    const name = row.id.slice("field-".length);
    const given = name in marks;
    row.className = !given ? "" : marks[name] ? "right" : "wrong";
    if (answer && name === answer.first_wrong) row.classList.add("first-wrong");
    row.querySelector("output").textContent = !given ? "" : marks[name] ? "✓" : "✗";
  }
  const verdict = document.getElementById("verdict");
  verdict.textContent = !answer ? "" : answer.correct ? "correct" : "not yet";
  verdict.className = !answer ? "" : answer.correct ? "right" : "wrong";
  document.getElementById("feedback").textContent = answer ? answer.feedback : "";
  document.getElementById("show-solution").disabled = !answer;
}

function showSolution() {
  document.getElementById("solution").innerHTML = marked.solution; // rendered by the API
  showFigure("solved-figure-box", "solved-figure", marked.solved_figure);
  const box = document.getElementById("solution-box");
  box.hidden = false;
  box.scrollIntoView();
}

document.addEventListener("DOMContentLoaded", async () => {
  if (!(await fillChoices("exercise-topics"))) return;
  document.getElementById("new").addEventListener("click", newExercise);
  document.getElementById("check").addEventListener("click", checkAnswer);
  document.getElementById("show-solution").addEventListener("click", showSolution);
  newExercise();
});
