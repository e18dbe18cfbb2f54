// Display formulas and tables wider than the screen scroll sideways (physcheck.css); make those, and
// only those, reachable with the keyboard so that they can be scrolled without a mouse.
"use strict";
function reachOverflowing() {
  for (const box of document.querySelectorAll('math[display="block"], .table-wrap')) {
    if (box.scrollWidth > box.clientWidth + 1) {
      box.tabIndex = 0;
    } else {
      box.removeAttribute("tabindex");
    }
  }
}
window.addEventListener("load", reachOverflowing);
window.addEventListener("resize", reachOverflowing);

// "line 12" beside an upload error: select that line in the text box, ready to be fixed.
document.addEventListener("click", (event) => {
  const link = event.target instanceof Element ? event.target.closest("a[data-line]") : null;
  const box = document.getElementById("source");
  if (!link || !box) {
    return;
  }
  event.preventDefault();
  const wanted = Number(link.dataset.line);
  const lines = box.value.split("\n");
  let start = 0;
  for (let index = 0; index < wanted - 1 && index < lines.length; index += 1) {
    start += lines[index].length + 1;
  }
  const end = start + (lines[wanted - 1] || "").length;
  box.focus();
  box.setSelectionRange(start, end);
  const lineHeight = parseFloat(getComputedStyle(box).lineHeight) || 20;
  box.scrollTop = Math.max(0, (wanted - 3) * lineHeight);
});

// The assignment builder's search filters the problem rows in place: its form's own GET (kept for a
// browser without script) reloads the page, losing the settings typed and the problems ticked.
(function () {
  const search = document.getElementById("problem-search");
  const box = document.getElementById("q");
  const count = document.getElementById("shown-count");
  if (!search || !box || !count) {
    return;
  }
  const rows = Array.from(document.querySelectorAll("table.problem-picker tbody tr[data-search]"));
  function filter() {
    const words = box.value.toLowerCase().split(/\s+/).filter(Boolean);
    let shown = 0;
    for (const row of rows) {
      const ticked = row.querySelector("input[type=checkbox]").checked;
      row.hidden = !ticked && !words.every((word) => row.dataset.search.includes(word));
      shown += row.hidden ? 0 : 1;
    }
    count.textContent = shown + (shown === 1 ? " problem" : " problems") + " listed";
  }
  box.addEventListener("input", filter);
  search.addEventListener("submit", (event) => {
    event.preventDefault();
    filter();
  });
})();

// The late penalty's fields only while late work is accepted: with it closed they set nothing.
(function () {
  const late = document.getElementById("a-late");
  const penalty = document.getElementById("late-penalty");
  if (!late || !penalty) {
    return;
  }
  const show = () => { penalty.hidden = late.value !== "penalty"; };
  late.addEventListener("change", show);
  show();
})();

// "Copy the join link": the link's text to the clipboard, said on the button (shown only where script
// runs; selecting the link by hand works everywhere).
for (const button of document.querySelectorAll("button[data-copy]")) {
  const source = document.getElementById(button.dataset.copy);
  if (!source || !navigator.clipboard) {
    continue;
  }
  const label = button.textContent;
  button.hidden = false;
  button.addEventListener("click", () => {
    navigator.clipboard.writeText(source.textContent.trim()).then(
      () => { button.textContent = "Copied"; },
      () => { button.textContent = "Select the link to copy it"; },
    );
    setTimeout(() => { button.textContent = label; }, 4000);
  });
}

// A new course's time zone: the browser's own rather than UTC, which an instructor in Paris would
// otherwise have to know to change (every date of the course is shown in it).
(function () {
  const zone = document.getElementById("course-zone");
  const own = Intl.DateTimeFormat().resolvedOptions().timeZone;
  if (zone && zone.value === "UTC" && own && !document.querySelector(".errors")) {  // not what was typed
    zone.value = own;
  }
})();
