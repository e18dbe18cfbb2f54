// The student pages: a student key kept in the tab (key mode), the live preview of how an answer is
// read (typeset as MathML by the server), submission through the JSON API, then the part's fresh
// standing and history from the server. HTML inserted here is only ever our own server's rendering,
// fetched from this origin; text from responses goes through textContent.
(function () {
  "use strict";
  var KEY_STORE = "physcheck-student-key";
  var root = document.getElementById("problem") || document.getElementById("problem-list");
  if (!root) { return; }
  var keyMode = root.getAttribute("data-mode") === "key";
  var problemId = root.getAttribute("data-problem");
  // The course the page was opened in (its assignment's): every request of the page names it, so that
  // answers are filed in that course even when the browser is signed in to another that has the problem.
  var course = root.getAttribute("data-course") || new URLSearchParams(window.location.search).get("course");

  function inCourse(url) { return course ? url + "?course=" + encodeURIComponent(course) : url; }

  function key() { return keyMode ? window.sessionStorage.getItem(KEY_STORE) : null; }

  function headers(json) {
    var h = { "Accept": json ? "application/json" : "text/html" };
    if (json) { h["Content-Type"] = "application/json"; }
    var k = key();
    if (k) {
      h["Authorization"] = "Bearer " + k;
    } else {
      var meta = document.querySelector('meta[name="csrf-token"]');
      if (meta) { h["X-CSRF-Token"] = meta.getAttribute("content"); }
    }
    return h;
  }

  function post(url, body) {
    return fetch(url, { method: "POST", headers: headers(true), body: JSON.stringify(body), credentials: "same-origin" })
      .then(function (response) {
        return response.json().catch(function () { return {}; }).then(function (data) {
          return { status: response.status, data: data, wait: response.headers.get("Retry-After") };
        });
      });
  }

  function getHtml(url) {
    return fetch(url, { headers: headers(false), credentials: "same-origin" }).then(function (response) {
      if (response.status !== 200) { throw new Error(String(response.status)); }
      return response.text().then(function (html) {
        var template = document.createElement("template");
        template.innerHTML = html;  // our own server-rendered, escaped fragment
        return template.content;
      });
    });
  }

  // A 429 says how long to wait (its Retry-After), and never signs anyone out.
  function waitText(seconds) {
    var n = parseInt(seconds || "", 10);
    if (!(n > 0)) { return "Too many requests at once; wait a moment and try again. Your work is kept."; }
    return "Too many requests at once; try again in " + n + " second" + (n === 1 ? "" : "s") + ". Your work is kept.";
  }

  function errorText(r) {
    if (r.status === 401) {
      return keyMode
        ? "Your key is no longer accepted; reload the page and enter it again."
        : "Your session has ended; open this activity again from your course.";
    }
    if (r.status === 429) { return waitText(r.wait); }
    return (r.data && r.data.error && r.data.error.message) || "Something went wrong; try again.";
  }

  // The answer as typed with the unreadable spot marked, e.g. "m g +▮" (DOM nodes, no HTML).
  function marked(text, position) {
    var line = document.createElement("p");
    line.className = "error-mark";
    var code = document.createElement("code");
    var at = Math.max(0, Math.min(position, text.length));
    code.appendChild(document.createTextNode(text.slice(0, at)));
    var mark = document.createElement("mark");
    mark.textContent = at < text.length ? text.charAt(at) : "\u2003";
    code.appendChild(mark);
    code.appendChild(document.createTextNode(text.slice(at + 1)));
    line.appendChild(document.createTextNode("Here: "));
    line.appendChild(code);
    return line;
  }

  function showPreview(preview, input, data, text) {
    preview.textContent = "";
    input.removeAttribute("aria-invalid");
    if (data.error) {
      input.setAttribute("aria-invalid", "true");
      var message = document.createElement("p");
      message.className = "preview-error";
      message.textContent = "Cannot read this yet: " + data.error.message;
      preview.appendChild(message);
      if (typeof data.error.position === "number") { preview.appendChild(marked(text, data.error.position)); }
      return;
    }
    if (!data.read_as) { return; }
    var line = document.createElement("div");
    line.className = "read-as";
    var label = document.createElement("span");
    label.textContent = "Read as: ";
    line.appendChild(label);
    if (data.mathml) {
      var holder = document.createElement("span");
      holder.innerHTML = data.mathml;  // MathML our server typeset from the parsed answer
      line.appendChild(holder);
    } else {
      var plain = document.createElement("code");
      plain.textContent = data.read_as.text;
      line.appendChild(plain);
    }
    preview.appendChild(line);
    if (data.read_as.note) {
      var note = document.createElement("p");
      note.className = "reading-note";
      note.textContent = data.read_as.note;
      preview.appendChild(note);
    }
  }

  var WORDS = { correct: "Correct.", incorrect: "Not correct.", invalid: "Could not read this answer." };

  // A free-body part: palette buttons add a force (a list row with a direction field, the diagram a
  // screen reader reads), arrows drawn from the body's centre; every change writes the answer box as
  // text ("weight 270; normal 110"), which is also what a student may type. An arrow can also be
  // dragged (mouse, pen or touch, through Pointer Events): its head, or anywhere round the body, turns
  // it to point at the pointer in 5° steps; the field and the answer follow, the keyboard path is the
  // same field.
  var SVG = "http://www.w3.org/2000/svg";
  var DEFAULT_ANGLE = { weight: 270, normal: 90, tension: 90, friction: 0, spring: 180, applied: 0, motion: 0 };
  var ARROW = 80;       // arrow length, in the canvas's units (its viewBox is 220 across)
  var HIT = 22;         // the head's hit radius: 44 units, 44 CSS px at the canvas's own size
  var SNAP = 5;         // degrees
  var DEAD = 6;         // nearer the centre than this, the pointer has no direction

  function svgEl(name, attrs) {
    var el = document.createElementNS(SVG, name);
    for (var a in attrs) { el.setAttribute(a, String(attrs[a])); }
    return el;
  }

  function gap(a, b) { return Math.abs(((a - b + 540) % 360) - 180); }

  function wireForces(editor, input, changed) {
    var list = editor.querySelector(".drawn-forces");
    var canvas = editor.querySelector(".force-canvas");
    var arrows = editor.querySelector(".arrows");
    var dragging = null;  // { field, start, pointer } while a pointer turns an arrow

    function fields() { return list.querySelectorAll("li input"); }

    function draw() {
      var rows = list.querySelectorAll("li");
      var parts = [];
      arrows.textContent = "";
      for (var i = 0; i < rows.length; i++) {
        var kind = rows[i].getAttribute("data-kind");
        var angle = Number(rows[i].querySelector("input").value) || 0;
        parts.push(kind + " " + angle);
        var rad = angle * Math.PI / 180;
        var cos = Math.cos(rad), sin = -Math.sin(rad);
        var tipX = Math.round(ARROW * cos), tipY = Math.round(ARROW * sin);
        var group = svgEl("g", { "class": "force" + (dragging && dragging.index === i ? " dragging" : ""), "data-index": i });
        group.appendChild(svgEl("line", { x1: 0, y1: 0, x2: Math.round((ARROW - 10) * cos), y2: Math.round((ARROW - 10) * sin),
          stroke: "currentColor", "stroke-width": 3 }));
        // The head: a ring that says "grab here" under a filled triangle, and a touch-sized clear hit area.
        group.appendChild(svgEl("circle", { "class": "handle", cx: tipX, cy: tipY, r: 9 }));
        var side = 6;
        var baseX = (ARROW - 12) * cos, baseY = (ARROW - 12) * sin;
        group.appendChild(svgEl("polygon", { "class": "head", fill: "currentColor", points: [
          tipX + "," + tipY,
          Math.round(baseX - side * sin) + "," + Math.round(baseY + side * cos),
          Math.round(baseX + side * sin) + "," + Math.round(baseY - side * cos)].join(" ") }));
        group.appendChild(svgEl("circle", { "class": "hit", cx: tipX, cy: tipY, r: HIT, fill: "transparent" }));
        // The name beyond the head, kept inside the canvas (about 6 units a letter); beside a level arrow it
        // goes under the head rather than over it.
        var room = 108 - 3 * kind.length;
        var labelX = Math.max(-room, Math.min(room, Math.round(100 * cos)));
        var labelY = Math.abs(cos) > 0.7 ? tipY + 24 : Math.round(100 * sin) + 4;
        var label = svgEl("text", { x: labelX, y: labelY, "font-size": 11, "text-anchor": "middle" });
        label.textContent = kind;
        group.appendChild(label);
        arrows.appendChild(group);
      }
      input.value = parts.join("; ");
    }
    function write() { draw(); changed(); }

    // The angle from the body's centre to the pointer, snapped; null at the very centre.
    function pointedAngle(event) {
      var point = canvas.createSVGPoint();
      point.x = event.clientX; point.y = event.clientY;
      var local = point.matrixTransform(canvas.getScreenCTM().inverse());
      if (Math.hypot(local.x, local.y) < DEAD) { return null; }
      var degrees = Math.atan2(-local.y, local.x) * 180 / Math.PI;
      return ((Math.round(degrees / SNAP) * SNAP) % 360 + 360) % 360;
    }

    canvas.addEventListener("pointerdown", function (event) {
      var all = fields();
      if (!all.length || input.disabled || all[0].disabled || event.button > 0) { return; }
      var angle = pointedAngle(event);
      if (angle === null) { return; }
      var grabbed = event.target.closest && event.target.closest("g.force");
      var index = grabbed ? Number(grabbed.getAttribute("data-index")) : 0;
      if (!grabbed) {  // pressed near the body, not on a head: turn the arrow nearest that way
        for (var i = 1; i < all.length; i++) {
          if (gap(Number(all[i].value) || 0, angle) < gap(Number(all[index].value) || 0, angle)) { index = i; }
        }
      }
      event.preventDefault();
      canvas.setPointerCapture(event.pointerId);
      dragging = { index: index, field: all[index], start: all[index].value, pointer: event.pointerId };
      dragging.field.value = String(angle);
      draw();
    });
    canvas.addEventListener("pointermove", function (event) {
      if (!dragging || event.pointerId !== dragging.pointer) { return; }
      var angle = pointedAngle(event);
      if (angle === null || String(angle) === dragging.field.value) { return; }
      dragging.field.value = String(angle);
      draw();
    });
    function finish(event, keep) {
      if (!dragging || event.pointerId !== dragging.pointer) { return; }
      if (!keep) { dragging.field.value = dragging.start; }  // the browser took the gesture: undo
      dragging = null;
      write();
    }
    canvas.addEventListener("pointerup", function (event) { finish(event, true); });
    canvas.addEventListener("pointercancel", function (event) { finish(event, false); });

    function add(kind, angle) {
      var row = document.createElement("li");
      row.setAttribute("data-kind", kind);
      var id = "force-" + Math.random().toString(36).slice(2);
      var name = document.createElement("label");
      name.setAttribute("for", id);
      name.textContent = kind + ", direction (degrees) ";
      var field = document.createElement("input");
      field.type = "number"; field.id = id; field.min = "0"; field.max = "359"; field.step = "1";
      field.value = String(angle);
      field.addEventListener("input", write);
      var remove = document.createElement("button");
      remove.type = "button"; remove.textContent = "Remove " + kind;
      remove.addEventListener("click", function () { row.remove(); write(); });
      row.appendChild(name); row.appendChild(field); row.appendChild(remove);
      list.appendChild(row);
      write();
      field.focus();
    }
    var buttons = editor.querySelectorAll(".add-force");
    for (var b = 0; b < buttons.length; b++) {
      buttons[b].addEventListener("click", function () {
        var kind = this.getAttribute("data-kind");
        add(kind, DEFAULT_ANGLE[kind] || 0);
      });
    }
  }

  function wire(form) {
    var part = form.getAttribute("data-part");
    var base = "/v1/problems/" + encodeURIComponent(problemId) + "/parts/" + encodeURIComponent(part);
    var input = form.querySelector("input[name=answer]");
    var button = form.querySelector("button[type=submit]");
    var preview = form.querySelector(".preview");
    var verdict = form.querySelector(".verdict");
    var section = form.closest(".part");
    var timer = null;
    var asked = 0;

    function askPreview() {
      window.clearTimeout(timer);
      var text = input.value;
      if (!text.trim()) { preview.textContent = ""; input.removeAttribute("aria-invalid"); return; }
      timer = window.setTimeout(function () {
        var mine = ++asked;
        post(inCourse(base + "/preview"), { answer: text }).then(function (r) {
          if (mine !== asked) { return; }  // a newer keystroke already asked again
          if (r.status !== 200) { preview.textContent = errorText(r); return; }
          showPreview(preview, input, r.data, text);
        }).catch(function () { preview.textContent = ""; });
      }, 300);
    }
    input.addEventListener("input", askPreview);
    // A choice part's radio buttons type the picked letter into the answer box.
    var choices = form.closest(".part").querySelectorAll("input.choice");
    for (var c = 0; c < choices.length; c++) {
      choices[c].addEventListener("change", function () { input.value = this.value; askPreview(); });
    }
    var editor = form.closest(".part").querySelector(".free-body-editor");
    if (editor) { wireForces(editor, input, askPreview); }

    function refresh(lead) {
      return getHtml(inCourse("/p/" + encodeURIComponent(problemId) + "/parts/" + encodeURIComponent(part) + "/work"))
        .then(function (fragment) {
          var work = fragment.querySelector(".work");
          var target = section.querySelector(".work");
          if (work && target) { target.innerHTML = work.innerHTML; }
          var standing = fragment.querySelector("#standing");
          var current = document.getElementById("standing");
          if (standing && current) { current.innerHTML = standing.innerHTML; }
          var released = fragment.querySelector("#solution-link");
          var link = document.getElementById("solution-link");
          if (released && link) { link.innerHTML = released.innerHTML; }  // this answer may have released it
          var latest = fragment.querySelector(".latest");
          verdict.textContent = "";
          if (lead) { verdict.appendChild(document.createTextNode(lead + " ")); }
          if (latest && !lead) {
            verdict.innerHTML = latest.innerHTML.trim();
            verdict.setAttribute("data-verdict", latest.getAttribute("data-verdict"));
          }
          var locked = (latest && latest.getAttribute("data-locked") === "true") || !!lead;
          if (locked) { input.disabled = true; button.disabled = true; }
        });
    }

    form.addEventListener("submit", function (event) {
      event.preventDefault();
      if (input.disabled) { return; }
      button.disabled = true;
      verdict.removeAttribute("data-verdict");
      verdict.textContent = "Checking…";
      post(inCourse(base + "/submissions"), { answer: input.value }).then(function (r) {
        if (r.status === 201) {
          return refresh(null).catch(function () {
            // Graded and stored, but the fresh standing could not be fetched: say the verdict at least.
            verdict.textContent = (WORDS[r.data.verdict] || "Checked.") + " Reload the page to see the feedback.";
          });
        }
        if (r.status === 409 && r.data.error && r.data.error.code === "attempts_exhausted") {
          return refresh("You have used all your attempts on this part.");
        }
        verdict.textContent = errorText(r);
      }).catch(function () {
        verdict.textContent = "The server could not be reached; your answer was not checked.";
      }).then(function () { if (!input.disabled) { button.disabled = false; } });
    });
  }

  function wireAll() {
    var forms = document.querySelectorAll("form.answer");
    for (var i = 0; i < forms.length; i++) { wire(forms[i]); }
  }

  function contentUrl() {
    var own = root.getAttribute("data-content");  // a page of its own, such as the worked solution
    if (own) { return inCourse(own); }
    return problemId ? inCourse("/p/" + encodeURIComponent(problemId) + "/content") : "/problems/content";
  }

  function loadWithKey(k) {
    var content = document.getElementById("content");
    var message = document.getElementById("key-error");
    return fetch(contentUrl(), { headers: { "Authorization": "Bearer " + k }, credentials: "omit" })
      .then(function (response) {
        if (response.status === 429) {  // the key is fine: keep it, say how long to wait
          message.textContent = waitText(response.headers.get("Retry-After"));
          return;
        }
        if (response.status === 404) { message.textContent = "There is no such problem."; return; }
        if (response.status !== 200) {
          if (response.status === 401) { window.sessionStorage.removeItem(KEY_STORE); }
          message.textContent = response.status === 401 ? "This key was not accepted." : "Something went wrong; try again.";
          return;
        }
        return response.text().then(function (html) {
          content.innerHTML = html;  // our own server-rendered fragment, fetched from this origin
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
      var k = document.getElementById("key").value.trim();
      if (!k) { return; }
      window.sessionStorage.setItem(KEY_STORE, k);
      loadWithKey(k);
    });
    var saved = window.sessionStorage.getItem(KEY_STORE);
    if (saved) { loadWithKey(saved); }
  } else {
    wireAll();
  }
})();
