// The student page: live preview of how an answer was read, and submission with its verdict.
// Talks only to the JSON API; everything it shows goes through textContent (never HTML).
(function () {
  "use strict";
  var root = document.getElementById("problem");
  if (!root) { return; }
  var problemId = root.getAttribute("data-problem");
  var KEY_STORE = "physcheck-student-key";
  var keyMode = root.getAttribute("data-mode") === "key";
  var base = "/v1/problems/" + encodeURIComponent(problemId) + "/parts/";

  function headers() {
    var h = { "Content-Type": "application/json", "Accept": "application/json" };
    var key = keyMode ? window.sessionStorage.getItem(KEY_STORE) : null;
    if (key) {
      h["Authorization"] = "Bearer " + key;
    } else {
      var meta = document.querySelector('meta[name="csrf-token"]');
      if (meta) { h["X-CSRF-Token"] = meta.getAttribute("content"); }
    }
    return h;
  }

  function post(url, body) {
    return fetch(url, { method: "POST", headers: headers(), body: JSON.stringify(body), credentials: "same-origin" })
      .then(function (response) {
        return response.json().catch(function () { return {}; }).then(function (data) {
          return { status: response.status, data: data };
        });
      });
  }

  function errorText(r) {
    if (r.status === 401) {
      // The API's own message names bearer headers: not something a student can act on.
      return keyMode
        ? "Your key is no longer accepted; reload the page and enter it again."
        : "Your session has ended; open this activity again from your course.";
    }
    return (r.data && r.data.error && r.data.error.message) || "Something went wrong; try again.";
  }

  // The server's reading is in its own syntax (`*`, `**`): show it the way students write maths.
  function readable(text) {
    return text.replace(/\*\*/g, "^").replace(/\*/g, "\u00b7");
  }

  // Feedback is written like problem statements, with `$...$` around maths; the page shows text
  // only (never HTML), so drop the delimiters rather than show them.
  function plainMaths(text) {
    return String(text).replace(/\\\$|\$/g, function (m) { return m === "$" ? "" : "$"; });
  }

  function sameWords(a, b) {
    function norm(s) { return String(s || "").trim().replace(/[.!\s]+$/, "").toLowerCase(); }
    return norm(a) === norm(b);
  }

  function wire(form) {
    var part = form.getAttribute("data-part");
    var input = form.querySelector("input[name=answer]");
    var preview = form.querySelector(".preview");
    var verdict = form.querySelector(".verdict");
    var timer = null;
    var asked = 0;

    input.addEventListener("input", function () {
      window.clearTimeout(timer);
      var text = input.value;
      if (!text.trim()) { preview.textContent = ""; return; }
      timer = window.setTimeout(function () {
        var mine = ++asked;
        post(base + encodeURIComponent(part) + "/preview", { answer: text }).then(function (r) {
          if (mine !== asked) { return; }  // a newer keystroke already asked again
          if (r.status !== 200) { preview.textContent = errorText(r); return; }
          if (r.data.error) {
            preview.textContent = "Cannot read this yet: " + r.data.error.message;
          } else if (r.data.read_as) {
            preview.textContent = "Read as: " + readable(r.data.read_as.text);
          }
        }).catch(function () { preview.textContent = ""; });
      }, 300);
    });

    form.addEventListener("submit", function (event) {
      event.preventDefault();
      var button = form.querySelector("button[type=submit]");
      button.disabled = true;
      verdict.textContent = "Checking…";
      post(base + encodeURIComponent(part) + "/submissions", { answer: input.value }).then(function (r) {
        verdict.removeAttribute("data-verdict");
        if (r.status !== 201) { verdict.textContent = errorText(r); return; }
        var d = r.data;
        var words = { correct: "Correct.", incorrect: "Not correct.", invalid: "Could not read this answer." };
        var word = words[d.verdict] || d.verdict;
        var lines = [word];
        // The judge's feedback for a right answer is often just "Correct.": say it once.
        if (d.feedback && !sameWords(d.feedback, word)) { lines.push(plainMaths(d.feedback)); }
        if (d.error && d.error.message && d.error.message !== d.feedback) { lines.push(d.error.message); }
        if (d.verdict === "incorrect" && d.score > 0 && d.score < 1) {
          lines.push("Partial credit: " + Math.round(d.score * 100) + "%.");
        }
        if (typeof d.attempts_used === "number") {
          lines.push("Attempts used: " + d.attempts_used +
            (typeof d.max_attempts === "number" ? " of " + d.max_attempts : "") + ".");
        }
        verdict.textContent = lines.join(" ");
        verdict.setAttribute("data-verdict", d.verdict);
      }).catch(function () {
        verdict.textContent = "The server could not be reached; your answer was not checked.";
      }).then(function () { button.disabled = false; });
    });
  }

  function wireAll() {
    var forms = document.querySelectorAll("form.answer");
    for (var i = 0; i < forms.length; i++) { wire(forms[i]); }
  }

  function loadWithKey(key) {
    var content = document.getElementById("content");
    var message = document.getElementById("key-error");
    return fetch("/p/" + encodeURIComponent(problemId) + "/content", {
      headers: { "Authorization": "Bearer " + key }, credentials: "omit"
    }).then(function (response) {
      if (response.status !== 200) {
        window.sessionStorage.removeItem(KEY_STORE);
        message.textContent = response.status === 404 ? "There is no such problem." : "This key was not accepted.";
        return;
      }
      return response.text().then(function (html) {
        // Our own server-rendered fragment (escaped there), fetched from this origin.
        content.innerHTML = html;
        var form = document.getElementById("key-form");
        if (form) { form.hidden = true; }
        wireAll();
        var heading = content.querySelector("h1");
        if (heading) { heading.setAttribute("tabindex", "-1"); heading.focus(); }
      });
    });
  }

  var keyForm = document.getElementById("key-form");
  if (keyForm) {
    keyForm.addEventListener("submit", function (event) {
      event.preventDefault();
      var key = document.getElementById("key").value.trim();
      if (!key) { return; }
      window.sessionStorage.setItem(KEY_STORE, key);
      loadWithKey(key);
    });
    var saved = window.sessionStorage.getItem(KEY_STORE);
    if (saved) { loadWithKey(saved); }
  } else {
    wireAll();
  }
})();
