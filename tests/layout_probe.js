// The layout rule of the browser check (tests/test_browser.py), run inside the page once MathJax has typeset it:
// every visible block of the text column either fits inside the column or sits inside a scroll box (overflow-x
// auto or scroll) that itself fits. A cell tagged full-width may use the page's main area instead of the column.
// Writes what breaks the rule, as JSON, into a new pre element (id layout-probe); the check reads it from the page
// (a phone's screen is a window 390 px wide).
(function () {
  function measure() {
    const col = document.querySelector("article.bd-article") || document.querySelector("main");
    const report = document.createElement("pre");
    report.id = "layout-probe";
    const page = document.documentElement.clientWidth;
    const main = document.querySelector(".bd-main") || col;
    // the column ends at its own right edge, or at the window's when the page itself is wider than the window
    const edge = (box) => Math.min(box.getBoundingClientRect().right, page) + 1;
    const limit = (el) => el.closest(".tag_full-width") ? edge(main) : edge(col);
    const boxed = (el) => {
      for (let p = el.parentElement; p && p !== col; p = p.parentElement) {
        const s = getComputedStyle(p);
        if ((s.overflowX === "auto" || s.overflowX === "scroll") && p.getBoundingClientRect().right <= limit(p)) return true;
      }
      return false;
    };
    const sticks = (el) => {
      const r = el.getBoundingClientRect();
      return r.width > 0 && r.height > 0 && r.right > limit(el) && !boxed(el) && !el.closest("mjx-assistive-mml");
    };
    const wide = [];
    if (col) {
      for (const el of col.querySelectorAll("*")) {
        if (!sticks(el) || (el.parentElement !== col && sticks(el.parentElement))) continue;  // the outermost is named
        const section = el.closest("section[id]");
        wide.push({tag: el.tagName.toLowerCase(), cls: String(el.className || "").slice(0, 60),
                   section: section ? section.id : "", over: Math.round(el.getBoundingClientRect().right - limit(el)),
                   text: (el.textContent || "").trim().replace(/\s+/g, " ").slice(0, 80)});
      }
    }
    report.textContent = JSON.stringify({width: page, column: col ? Math.round(edge(col)) : null, wide: wide});
    document.body.appendChild(report);
  }
  window.addEventListener("load", function () {
    if (window.MathJax && MathJax.startup && MathJax.startup.promise) MathJax.startup.promise.then(() => setTimeout(measure, 100));
    else setTimeout(measure, 100);
  });
})();
