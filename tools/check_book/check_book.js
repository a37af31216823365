// The book's browser check, run by tools/check_book/check_book.sh inside headless Chromium: loads pages of the book in
// an iframe as wide as a browser window, lets MathJax finish, and lists what a reader would see broken: formula
// errors, raw formula commands and other raw markup (an escaped '|', '--' printed as a dash, \ref), missing
// images, links to missing files or anchors, and figures, tables or formulas wider than the text column.
//
// It reads window.CHECK_BOOK = {root: "file:///.../html/", pages: ["ch01.html", ...], allPages: [...],
// widths: [1280, 800], concurrency: 3}, written by check_book.sh into pages.js: check_book.sh shares the book's
// pages (allPages) among several Chromium processes, one core each, and this one checks `pages`. A link into one of
// allPages may name an anchor that only another process sees (the anchors a page defines once its scripts ran), so
// those links are left to check_book.sh, which merges the processes' findings. The findings are written into
// <pre id="verdict">, one per line, fields separated by tabs:
//   P problem            a problem, as "page: what is wrong"
//   A page id            an anchor one of `pages` defines      G page   that page exists (its anchors are listed)
//   L page file anchor href   a link into allPages with an anchor, to be matched against the A lines
//   N count              the number of links that stay inside the book
//   X message            the checker itself failed
// Chromium must run with --allow-file-access-from-files, so that this page may read the documents of the iframes
// it loads.
"use strict";

(function () {
  const config = window.CHECK_BOOK;
  const verdict = document.getElementById("verdict");
  const problems = new Set();                  // "page: what is wrong", each reported once
  const anchors = new Map();                   // page -> Set of ids and names it defines
  const links = [];                            // {page, file, anchor}: every link that stays inside the book
  const rootPath = new URL(config.root).pathname;
  // A page must be loaded and typeset within this time, or it is reported as not finishing. The time is
  // virtual (check_book.sh runs Chromium with --virtual-time-budget), so idle waits cost nothing real.
  const pageTimeoutMs = 60000;

  function report(page, what) { problems.add(page + ": " + what); }

  function shorten(text, length) {
    text = text.replace(/\s+/g, " ").trim();
    return text.length > length ? text.slice(0, length - 3) + "..." : text;
  }

  function delay(ms) { return new Promise(resolve => setTimeout(resolve, ms)); }

  // Resolves when `frame` has loaded `url` (the load event waits for images and the page's own scripts).
  function load(frame, url) {
    return new Promise(resolve => {
      frame.onload = () => { frame.onload = null; resolve(); };
      frame.src = url;
    });
  }

  // Resolves when MathJax has typeset the page: after its startup and then after everything it has queued.
  // Rejects when MathJax does not appear at all (its scripts missing from the book).
  async function mathjaxDone(win) {
    for (let waited = 0; !(win.MathJax && win.MathJax.Hub && win.MathJax.Hub.Register); waited += 20) {
      if (waited > 5000) throw new Error("MathJax did not load (is build/docs/html/mathjax there?)");
      await delay(20);
    }
    await new Promise(resolve => win.MathJax.Hub.Register.StartupHook("End", resolve));
    await new Promise(resolve => win.MathJax.Hub.Queue(resolve));
  }

  // Every formula MathJax could not typeset, named by its TeX source.
  function checkFormulas(page, win, doc) {
    for (const jax of win.MathJax.Hub.getAllJax()) {
      const frame = doc.getElementById(jax.inputID + "-Frame");
      const error = frame && frame.querySelector(".merror, .MathJax_Error");
      if (error) report(page, "formula error '" + shorten(error.textContent, 80) + "' in \\(" +
                              shorten(jax.originalText, 80) + "\\)");
    }
    for (const error of doc.querySelectorAll(".MathJax_Error"))
      report(page, "MathJax failed: " + shorten(error.textContent, 80));
  }

  // Doxygen leaves a formula command as text where it ignores it (inside double quotes, for one, or in a comment
  // of a listing): anywhere outside the formulas MathJax typeset.
  function checkRawCommands(page, doc) {
    const walker = doc.createTreeWalker(doc.body, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      if (node.parentElement.closest("script, style, .MathJax, .MathJax_Display, .MathJax_Preview")) continue;
      const at = node.data.search(/\\f[$[\]{}]/);
      if (at >= 0) report(page, "raw formula command in the text: '" +
                                shorten(node.data.slice(Math.max(0, at - 30), at + 50), 80) + "'");
    }
  }

  // Markup a reader should never see, in any text of the page, listings included (a formula's own TeX, inside
  // MathJax's scripts and output, is left alone):
  // - a backslash before `|`: Markdown's escape of a table's column bar, kept literally inside a code span;
  // - an en dash (U+2013) right before a flag name: Doxygen's rendering of `--` outside a code span;
  // - a raw \ref: a Doxygen command inside a string of a listing or where Doxygen does not read commands. The
  //   source browser's pages (NAME_source.html) show each file verbatim, including the code that writes \ref
  //   into the book's tables, so this one pattern is not applied there;
  // - a character entity shown as its code (`&#124;`, `&amp;`): Doxygen escapes the ampersand of one written in
  //   a Markdown table cell. Named ones only of the few HTML always has, since a listing's C++ (`&v;`) looks like
  //   the others; not applied to the source pages either, whose code may write one.
  const markupPatterns = [
    [/\\\|/, "a backslash before '|' (an escaped table bar shown literally)", true],
    [/(^|[\s(\[`'"])\u2013[a-zA-Z][a-zA-Z0-9-]*/, "an en dash before a flag name ('--' printed as a dash)", true],
    [/\\ref\b/, "raw \\ref markup", false],
    [/&(#[0-9]+|#x[0-9a-fA-F]+|amp|lt|gt|quot|nbsp);/, "a character entity shown as its code", false],
  ];
  function checkRawMarkup(page, doc) {
    const sourcePage = /_source\.html$/.test(page);
    const walker = doc.createTreeWalker(doc.body, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      if (node.parentElement.closest("script, style, .MathJax, .MathJax_Display, .MathJax_Preview")) continue;
      for (const [pattern, what, inSources] of markupPatterns) {
        if (sourcePage && !inSources) continue;
        const match = pattern.exec(node.data);
        if (!match) continue;
        const at = match.index + (match[1] ? match[1].length : 0);
        report(page, what + ": '" + shorten(node.data.slice(Math.max(0, at - 30), at + 40), 80) + "'");
      }
    }
  }

  function loadsOnItsOwn(src) {
    return new Promise((resolve) => {
      const probe = new Image();
      probe.onload = () => resolve(probe.naturalWidth > 0);
      probe.onerror = () => resolve(false);
      probe.src = src;
    });
  }

  // An image not yet decoded when the page's load event fired (an SVG, at times) gets the time to decode: only
  // one that cannot be (missing, or not an image) is reported.
  async function checkImages(page, doc) {
    for (const img of doc.images) {
      if (img.complete && img.naturalWidth > 0) continue;
      let decoded = await img.decode().then(() => true, () => false);
      // decode() can also reject for an image that is fine but was not rendered yet on a busy machine: load the
      // file once more on its own, where only a missing or undecodable file fails.
      if (!decoded) decoded = await loadsOnItsOwn(img.src);
      if (!decoded) report(page, "image '" + img.getAttribute("src") + "' is missing or cannot be decoded");
    }
  }

  // Records the anchors this page defines and the links it holds; they are matched once every page is loaded.
  function collectLinks(page, doc) {
    const ids = new Set();
    for (const element of doc.querySelectorAll("[id]")) ids.add(element.id);
    for (const element of doc.querySelectorAll("a[name]")) ids.add(element.getAttribute("name"));
    anchors.set(page, ids);
    for (const a of doc.querySelectorAll("a[href]")) {
      const url = new URL(a.href);
      if (url.protocol !== "file:") continue;  // the web (http, https, mailto) and javascript: are not checked
      const path = decodeURIComponent(url.pathname);
      if (!path.startsWith(decodeURIComponent(rootPath))) {
        report(page, "link '" + a.getAttribute("href") + "' leaves the book");
        continue;
      }
      links.push({page, file: path.slice(decodeURIComponent(rootPath).length),
                  anchor: decodeURIComponent(url.hash.slice(1)), href: a.getAttribute("href")});
    }
  }

  // The part of `element` a reader sees, clipped by any ancestor below `column` that scrolls or hides overflow.
  function visibleRight(win, element, column) {
    let right = element.getBoundingClientRect().right;
    for (let a = element.parentElement; a && a !== column; a = a.parentElement)
      if (win.getComputedStyle(a).overflowX !== "visible") right = Math.min(right, a.getBoundingClientRect().right);
    return right;
  }

  function describe(element) {
    if (element.tagName === "IMG") return "figure '" + element.getAttribute("src") + "'";
    if (element.tagName === "TABLE") {
      const cell = element.querySelector("th, td");
      return "table '" + shorten(cell ? cell.textContent : "", 40) + "'";
    }
    const script = element.nextElementSibling;
    return "formula \\[" + shorten(script ? script.textContent : element.textContent, 60) + "\\]";
  }

  // Figures, tables and displayed formulas that reach past the right edge of the text column (div.contents), and
  // code blocks whose lines do not fit their box and cannot be scrolled into view.
  function checkWidths(page, win, doc, width) {
    for (const block of doc.querySelectorAll("div.contents div.fragment, div.contents pre")) {
      const overflow = win.getComputedStyle(block).overflowX;
      if (block.scrollWidth > block.clientWidth + 1 && overflow !== "auto" && overflow !== "scroll")
        report(page, "code block '" + shorten(block.textContent, 40) + "' is cut off: its lines are " +
                     block.scrollWidth + " px wide, its box " + block.clientWidth + " px at a " + width + " px window");
    }
    for (const column of doc.querySelectorAll("div.contents")) {
      const box = column.getBoundingClientRect();
      if (box.width === 0) continue;
      for (const element of column.querySelectorAll("img, table, .MathJax_Display")) {
        const rect = element.getBoundingClientRect();
        if (rect.width === 0) continue;  // hidden (a collapsed section)
        if (visibleRight(win, element, column) > box.right + 1)
          report(page, describe(element) + " is " + Math.round(rect.width) + " px wide, wider than the " +
                       Math.round(box.width) + " px text column at a " + width + " px window");
      }
    }
  }

  async function checkPage(frame, page) {
    frame.style.width = config.widths[0] + "px";
    await load(frame, config.root + page);
    const win = frame.contentWindow, doc = frame.contentDocument;
    // Doxygen writes a formula as \( ... \) or \[ ... \] for MathJax, which replaces each with a
    // <script type="math/tex"> as it typesets; a page with neither (most of the API reference) need not wait.
    if (/\\[([]/.test(doc.body.textContent) || doc.querySelector('script[type^="math/tex"]')) {
      try {
        await mathjaxDone(win);
        checkFormulas(page, win, doc);
      } catch (error) {
        report(page, error.message);
      }
    }
    checkRawCommands(page, doc);
    checkRawMarkup(page, doc);
    await checkImages(page, doc);
    collectLinks(page, doc);
    for (const width of config.widths) {
      if (frame.style.width !== width + "px") {
        frame.style.width = width + "px";
        win.dispatchEvent(new win.Event("resize"));  // Doxygen's resize.js lays out the side bar on resize
        await delay(50);
      }
      checkWidths(page, win, doc, width);
    }
  }

  async function checkPageWithTimeout(frame, page) {
    let timer;
    const timeout = new Promise((_, reject) => {
      timer = setTimeout(() => reject(new Error("did not finish loading and typesetting")), pageTimeoutMs);
    });
    try {
      await Promise.race([checkPage(frame, page), timeout]);
    } catch (error) {
      report(page, error.message);
    } finally {
      clearTimeout(timer);
    }
  }

  // A file that is not one of the checked pages (an image, a script, or a page left out of a partial check):
  // null when it does not exist, else the anchors it defines if it is a page (as written, before any script ran).
  function readTarget(file) {
    return new Promise(resolve => {
      const request = new XMLHttpRequest();
      request.onload = () => {
        const ids = new Set();
        if (/\.html$/.test(file)) {
          const doc = new DOMParser().parseFromString(request.responseText, "text/html");
          for (const element of doc.querySelectorAll("[id]")) ids.add(element.id);
          for (const element of doc.querySelectorAll("a[name]")) ids.add(element.getAttribute("name"));
        }
        resolve(ids);
      };
      request.onerror = () => resolve(null);
      request.open("GET", config.root + file);
      request.send();
    });
  }

  // Links into allPages with an anchor are left to check_book.sh (see the top of this file); links to a page of
  // allPages without one need no check (the page exists), and the rest (images, scripts, pages outside a partial
  // check) are read here.
  async function checkLinks(deferred) {
    const bookPages = new Set(config.allPages);
    const targets = new Map(anchors);  // file -> its anchors, or null when it does not exist
    for (const link of links) {
      if (bookPages.has(link.file)) {
        if (link.anchor) deferred.add(["L", link.page, link.file, link.anchor, link.href].map(field).join("\t"));
        continue;
      }
      if (!targets.has(link.file)) targets.set(link.file, await readTarget(link.file));
      const ids = targets.get(link.file);
      if (ids === null) report(link.page, "link '" + link.href + "': no such file");
      else if (link.anchor && /\.html$/.test(link.file) && !ids.has(link.anchor))
        report(link.page, "link '" + link.href + "': " + link.file + " has no anchor '" + link.anchor + "'");
    }
    // A page that did not finish has its anchors read as written, before any script ran.
    for (const page of config.pages)
      if (!anchors.has(page)) anchors.set(page, await readTarget(page));
  }

  // One field of a verdict line: tabs and line breaks would split it.
  function field(text) { return String(text).replace(/[\t\n\r]/g, " "); }

  async function main() {
    const queue = config.pages.slice();
    const workers = [];
    for (let k = 0; k < Math.min(config.concurrency, queue.length); ++k) {
      const frame = document.createElement("iframe");
      frame.style.height = "900px";
      document.getElementById("frames").appendChild(frame);
      workers.push((async () => {
        for (let page = queue.shift(); page !== undefined; page = queue.shift())
          await checkPageWithTimeout(frame, page);
      })());
    }
    await Promise.all(workers);
    const deferred = new Set();
    await checkLinks(deferred);
    document.getElementById("frames").remove();
    const lines = Array.from(problems, problem => "P\t" + field(problem));
    for (const [page, ids] of anchors) {
      if (ids === null) continue;
      lines.push("G\t" + field(page));
      for (const id of ids) lines.push("A\t" + field(page) + "\t" + field(id));
    }
    lines.push(...deferred);
    lines.push("N\t" + links.length);
    verdict.textContent = lines.join("\n");
    verdict.setAttribute("data-done", "yes");
  }

  main().catch(error => {
    verdict.textContent = "X\tthe checker itself failed: " + field(error);
    verdict.setAttribute("data-done", "yes");
  });
})();
