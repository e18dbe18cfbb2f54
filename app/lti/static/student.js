// The student page: live preview of how an answer was read, submission with its verdict, and on
// load each part's earlier work (last answer, its verdict, attempts used) from the submissions list.
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

  var WORDS = { correct: "Correct.", incorrect: "Not correct.", invalid: "Could not read this answer." };

  // A verdict in words: from a submission's response, or an earlier one from the submissions list.
  function describe(d) {
    var word = WORDS[d.verdict] || String(d.verdict);
    var lines = [word];
    // The judge's feedback for a right answer is often just "Correct.": say it once.
    if (d.feedback && !sameWords(d.feedback, word)) { lines.push(plainMaths(d.feedback)); }
    if (d.error && d.error.message && d.error.message !== d.feedback) { lines.push(d.error.message); }
    if (d.verdict === "incorrect" && d.score > 0 && d.score < 1) {
      lines.push("Partial credit: " + Math.round(d.score * 100) + "%.");
    }
    return lines;
  }

  function attemptsText(used, limit) {
    return "Attempts used: " + used + (limit ? " of " + limit : "") + ".";
  }

  function wire(form) {
    var part = form.getAttribute("data-part");
    var input = form.querySelector("input[name=answer]");
    var preview = form.querySelector(".preview");
    var verdict = form.querySelector(".verdict");
    var earlier = form.querySelector(".earlier");
    var timer = null;
    var asked = 0;
    // Once the student types or submits, the earlier work must not overwrite what they are doing.
    var touched = false;

    function limit() {
      var value = parseInt(form.getAttribute("data-max-attempts") || "", 10);
      return value > 0 ? value : null;
    }

    input.addEventListener("input", function () {
      touched = true;
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
            preview.textContent = "Read as: " + readable(r.data.read_as.text) +
              (r.data.read_as.note ? " (" + r.data.read_as.note + ")" : "");
          }
        }).catch(function () { preview.textContent = ""; });
      }, 300);
    });

    form.addEventListener("submit", function (event) {
      event.preventDefault();
      touched = true;
      if (earlier) { earlier.hidden = true; }
      var button = form.querySelector("button[type=submit]");
      button.disabled = true;
      verdict.textContent = "Checking…";
      post(base + encodeURIComponent(part) + "/submissions", { answer: input.value }).then(function (r) {
        verdict.removeAttribute("data-verdict");
        if (r.status !== 201) { verdict.textContent = errorText(r); return; }
        var d = r.data;
        if (typeof d.max_attempts === "number" && d.max_attempts > 0) {
          form.setAttribute("data-max-attempts", String(d.max_attempts));
        }
        var lines = describe(d);
        if (typeof d.attempts_used === "number") { lines.push(attemptsText(d.attempts_used, limit())); }
        verdict.textContent = lines.join(" ");
        verdict.setAttribute("data-verdict", d.verdict);
      }).catch(function () {
        verdict.textContent = "The server could not be reached; your answer was not checked.";
      }).then(function () { button.disabled = false; });
    });

    // The part's last submission (any verdict) and its count of graded ones (invalid uses none).
    function restore(last, used) {
      if (touched || !earlier) { return; }
      input.value = last.answer;
      earlier.textContent = "Your last answer: " + describe(last).concat([attemptsText(used, limit())]).join(" ");
      earlier.setAttribute("data-verdict", last.verdict);
      earlier.hidden = false;
    }

    return { part: part, student: form.getAttribute("data-student"), restore: restore };
  }

  var MAX_PAGES = 20;  // 20 000 submissions to one problem by one student: enough, and bounded

  function getJson(url) {
    return fetch(url, { headers: headers(), credentials: "same-origin" }).then(function (response) {
      if (response.status !== 200) { throw new Error("HTTP " + response.status); }
      return response.json();
    });
  }

  // Every submission of this student to this problem, oldest first, following the API's cursor.
  function submissions(student) {
    var url = "/v1/submissions?problem=" + encodeURIComponent(problemId) + "&limit=1000&student=" +
      encodeURIComponent(student);
    var items = [];
    function page(cursor, left) {
      return getJson(url + (cursor ? "&cursor=" + encodeURIComponent(cursor) : "")).then(function (data) {
        items = items.concat(data.items || []);
        return data.next && left > 1 ? page(data.next, left - 1) : items;
      });
    }
    return page(null, MAX_PAGES);
  }

  function restoreEarlierWork(parts) {
    // Without the page's student named, an instructor's list would be everyone's work: show none.
    var student = parts.length ? parts[0].student : null;
    if (!student) { return; }
    submissions(student).then(function (items) {
      var last = Object.create(null);  // keyed by part ids, which are not ours to trust as plain keys
      var used = Object.create(null);
      items.forEach(function (item) {
        if (item.student !== student) { return; }  // the API filtered already; this page trusts no list
        last[item.part] = item;
        if (item.verdict !== "invalid") { used[item.part] = (used[item.part] || 0) + 1; }
      });
      parts.forEach(function (p) {
        if (last[p.part]) { p.restore(last[p.part], used[p.part] || 0); }
      });
    }).catch(function () { /* Earlier work is a convenience: the page works without it. */ });
  }

  function wireAll() {
    var forms = document.querySelectorAll("form.answer");
    var parts = [];
    for (var i = 0; i < forms.length; i++) { parts.push(wire(forms[i])); }
    restoreEarlierWork(parts);
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
