// MathJax 3 (mathjax-full, from npm, for the typesetting comparison only: pages never load it) turns
// TeX into SVG: reads [{tex, display}] as JSON on stdin, writes {css, svgs: [...]} as JSON on stdout.
"use strict";
const path = require("path");
const root = process.env.PHYSCHECK_MATHJAX || path.join(__dirname, "..", "..", ".mathjax", "node_modules");
const load = (p) => require(path.join(root, "mathjax-full", "js", p));
const { mathjax } = load("mathjax.js");
const { TeX } = load("input/tex.js");
const { SVG } = load("output/svg.js");
const { liteAdaptor } = load("adaptors/liteAdaptor.js");
const { RegisterHTMLHandler } = load("handlers/html.js");
const { AllPackages } = load("input/tex/AllPackages.js");

const adaptor = liteAdaptor();
RegisterHTMLHandler(adaptor);
const svg = new SVG({ fontCache: "none" });
const doc = mathjax.document("", { InputJax: new TeX({ packages: AllPackages }), OutputJax: svg });
let input = "";
process.stdin.on("data", (chunk) => { input += chunk; });
process.stdin.on("end", () => {
  const items = JSON.parse(input);
  const svgs = items.map((item) => {
    try {
      return adaptor.outerHTML(doc.convert(item.tex, { display: item.display, em: 16, ex: 8, containerWidth: 1000 }));
    } catch (error) {
      return "<code>MathJax: " + String(error.message || error) + "</code>";
    }
  });
  process.stdout.write(JSON.stringify({ css: adaptor.textContent(svg.styleSheet(doc)), svgs }));
});
