// The live demos of the book's pages: each <div class="cloth-demo"> runs the book's own core, compiled to
// WebAssembly (cloth_web.js, web/cloth_web.cpp), draws the cloth on a canvas and plots its energy. A demo is
// described by its attributes:
//   data-flags     the command line of ch10_cloth it starts from ("--K 200 --damping 20 --dt 0.01")
//   data-methods   the methods it runs side by side, one cloth each ("explicit_euler symplectic_euler")
//   data-controls  the flags the reader may change ("method K damping dt t-end")
//   data-hmax      "yes": show the predicted largest stable step of the chosen explicit Runge-Kutta method
// The page's URL may set any flag by its name without the dashes (ch03.html?method=rk4&K=200&dt=0.01); `tableau`
// is another name for `method`; `play` starts the animation at once. With `autorun` the demo runs to the end at once and writes the final state in
// final.dat's format into the element with id `final-state`, the line a stopped run prints (or "ok") into
// `run-status` and the run's command line (ch10_cloth's flags) into `run-arguments`, so that a script can run
// the native program on the same flags and compare (tools/check_demos.sh); `measure` first times the whole run as
// the native program does (run.txt's wall_seconds / steps) and writes the seconds per step into `step-cost`.
"use strict";

(function () {
  const palette = ["#c0392b", "#2471a3", "#1e8449", "#7d3c98"];

  // The flags given in the page's URL, as [flag, value] pairs, and the switches autorun and measure.
  function urlSettings() {
    const query = new URLSearchParams(window.location.search);
    const settings = {flags: [], methods: null, autorun: query.has("autorun"), play: query.has("play"), measure: false};
    for (const [name, value] of query) {
      if (name === "autorun" || name === "play") continue;
      if (name === "measure") settings.measure = true;
      else if (name === "method" || name === "tableau") settings.methods = [value];
      else settings.flags.push(["--" + name, value]);
    }
    return settings;
  }

  // "--K 200 --dt 0.01" as [flag, value] pairs.
  function parseFlags(text) {
    const words = (text || "").trim().split(/\s+/).filter((w) => w.length > 0);
    const pairs = [];
    for (let k = 0; k + 1 < words.length; k += 2) pairs.push([words[k], words[k + 1]]);
    return pairs;
  }

  // Pairs with later ones replacing earlier ones of the same flag.
  function merged(...lists) {
    const out = new Map();
    for (const list of lists) for (const [flag, value] of list) out.set(flag, value);
    return [...out.entries()];
  }

  function element(tag, attributes, text) {
    const e = document.createElement(tag);
    for (const [k, v] of Object.entries(attributes || {})) e.setAttribute(k, v);
    if (text !== undefined) e.textContent = text;
    return e;
  }

  // The module, loaded once for every demo of the page from the file beside the page.
  let modulePromise = null;
  function loadModule() {
    if (modulePromise) return modulePromise;
    modulePromise = new Promise((resolve, reject) => {
      const script = element("script", {src: "cloth_web.js"});
      script.onload = () => {
        if (typeof ClothModule !== "function") reject(new Error("cloth_web.js defines no ClothModule"));
        else {
          // Compiled synchronously (the module is built so), the factory returns the module itself; a build
          // that compiles asynchronously returns a promise of it.
          const module = ClothModule();
          if (typeof module.then === "function") module.then(resolve, reject);
          else resolve(module);
        }
      };
      script.onerror = () => reject(new Error("cloth_web.js could not be loaded"));
      document.head.appendChild(script);
    });
    return modulePromise;
  }

  // An oblique view: the rest sheet lies in the plane z = 0 with gravity along -z, so the picture's axes are y
  // (across) and z (up), and x, the depth, is drawn receding at half scale up and to the left, so that a sheet
  // hung flat and one fallen vertical both show their area.
  function project(x, y, z) {
    const angle = 0.6;
    return [y - 0.5 * x * Math.cos(angle), z + 0.5 * x * Math.sin(angle)];
  }

  class Demo {
    constructor(root, module, url) {
      this.root = root;
      this.module = module;
      this.url = url;
      this.baseFlags = parseFlags(root.dataset.flags);
      this.methods = url.methods || (root.dataset.methods || "implicit_euler").split(/\s+/);
      this.controls = (root.dataset.controls || "").split(/\s+/).filter((c) => c.length > 0);
      this.showHMax = root.dataset.hmax === "yes";
      this.runs = [];
      this.playing = false;
      this.build();
      this.reset();
    }

    build() {
      const root = this.root;
      root.textContent = "";
      const bar = element("div", {class: "cloth-demo-controls"});
      this.inputs = new Map();
      const initial = new Map(merged(this.baseFlags, this.url.flags));
      for (const name of this.controls) {
        const label = element("label", {}, name === "method" ? "method " : "--" + name + " ");
        let input;
        if (name === "method") {
          input = element("select");
          for (const line of this.module.methods().trim().split("\n")) {
            const [method, title] = line.split("\t");
            const option = element("option", {value: method}, title + " (" + method + ")");
            if (method === this.methods[0]) option.selected = true;
            input.appendChild(option);
          }
        } else {
          input = element("input", {type: "text", size: "8", value: initial.get("--" + name) || "",
                                    placeholder: "default"});
        }
        input.addEventListener("change", () => this.reset());
        label.appendChild(input);
        bar.appendChild(label);
        this.inputs.set(name, input);
      }
      this.playButton = element("button", {type: "button"}, "Play");
      this.playButton.addEventListener("click", () => this.toggle());
      const resetButton = element("button", {type: "button"}, "Reset");
      resetButton.addEventListener("click", () => this.reset());
      bar.append(this.playButton, resetButton);
      root.appendChild(bar);

      const width = Math.max(240, Math.min(root.clientWidth || 640, 720));
      this.cloth = element("canvas", {width: String(width), height: String(Math.round(width * 0.5))});
      this.plot = element("canvas", {width: String(width), height: String(Math.round(width * 0.3))});
      this.status = element("div", {class: "cloth-demo-status"});
      this.legend = element("div", {class: "cloth-demo-legend"});
      root.append(this.cloth, this.legend, this.plot, this.status);
    }

    // The flags of the runs: the page's, then the URL's, then the reader's inputs.
    flags() {
      const typed = [];
      for (const [name, input] of this.inputs)
        if (name !== "method" && input.value.trim() !== "") typed.push(["--" + name, input.value.trim()]);
      return merged(this.baseFlags, this.url.flags, typed);
    }

    reset() {
      for (const run of this.runs) run.run.delete();
      this.runs = [];
      const methods = this.inputs.has("method") ? [this.inputs.get("method").value] : this.methods;
      const flags = this.flags();
      this.error = "";
      for (const method of methods) {
        const args = ["--method", method];
        for (const [flag, value] of flags) args.push(flag, value);
        const run = new this.module.Run(args.join("\n"));
        if (!run.valid()) {
          this.error = run.error();
          run.delete();
          continue;
        }
        this.runs.push({run, method, args, energy: [[0, run.energy()[3]]]});
      }
      this.hMax = "";
      if (this.showHMax && this.runs.length > 0) {
        const h = this.runs[0].run.predictedHMax();
        this.hMax = h > 0 ? "predicted h_max = " + h.toPrecision(4) + " s (the fastest mode at rest)" : "";
      }
      this.pause();
      this.draw();
    }

    toggle() { if (this.playing) this.pause(); else this.play(); }
    play() {
      if (!this.runs.some((r) => r.run.running())) return;
      this.playing = true;
      this.playButton.textContent = "Pause";
      const frame = () => {
        if (!this.playing) return;
        this.advance();
        this.draw();
        if (this.runs.some((r) => r.run.running())) window.requestAnimationFrame(frame);
        else this.pause();
      };
      window.requestAnimationFrame(frame);
    }
    pause() {
      this.playing = false;
      this.playButton.textContent = "Play";
    }

    // One animation frame: about 1/60 s of simulated time per frame, but no more than ~15 ms of computing.
    advance() {
      const start = performance.now();
      for (const r of this.runs) {
        const target = r.run.time() + 1 / 60;
        while (r.run.running() && r.run.time() < target - 1e-12 && performance.now() - start < 15) {
          r.run.advance(1);
          r.energy.push([r.run.time(), r.run.energy()[3]]);
        }
      }
    }

    // Runs every run to its end at once (autorun), recording its energy at every step.
    finish() {
      for (const r of this.runs)
        while (r.run.running()) {
          r.run.advance(1);
          r.energy.push([r.run.time(), r.run.energy()[3]]);
        }
      this.draw();
    }

    draw() {
      this.drawCloth();
      this.drawEnergy();
      const lines = [];
      if (this.error) lines.push(this.error);
      for (const r of this.runs) {
        const stop = r.run.stopMessage();
        lines.push(stop || r.method + ": t = " + r.run.time().toFixed(3) + " s, step " + r.run.steps() + " of " +
                   r.run.totalSteps() + ", E = " + r.run.energy()[3].toPrecision(6) + " J");
      }
      if (this.hMax) lines.push(this.hMax);
      this.status.textContent = lines.join("\n");
      this.status.classList.toggle("cloth-demo-stopped", this.error !== "" ||
                                   this.runs.some((r) => r.run.stopMessage() !== ""));
    }

    drawCloth() {
      const c = this.cloth.getContext("2d");
      c.clearRect(0, 0, this.cloth.width, this.cloth.height);
      if (this.runs.length === 0) return;
      const n = this.runs.length;
      const panel = this.cloth.width / n;
      this.legend.textContent = "";
      this.runs.forEach((r, k) => {
        const M = r.run.rows(), N = r.run.columns();
        const p = r.run.positions();
        const xy = new Float64Array(2 * M * N);
        for (let q = 0; q < M * N; ++q) {
          const [u, w] = project(p[3 * q], p[3 * q + 1], p[3 * q + 2]);
          xy[2 * q] = u;
          xy[2 * q + 1] = w;
        }
        // Each cloth's picture scale grows to hold it and never shrinks, so that a sag is seen as a sag (and a
        // cloth flying apart does not shrink its neighbour to a dot).
        if (!r.bounds) r.bounds = [Infinity, -Infinity, Infinity, -Infinity];
        const b = r.bounds;
        for (let q = 0; q < M * N; ++q) {
          b[0] = Math.min(b[0], xy[2 * q]); b[1] = Math.max(b[1], xy[2 * q]);
          b[2] = Math.min(b[2], xy[2 * q + 1]); b[3] = Math.max(b[3], xy[2 * q + 1]);
        }
        const span = Math.max(b[1] - b[0], b[3] - b[2], 1e-9);
        const scale = 0.9 * Math.min(panel, this.cloth.height) / span;
        const u0 = k * panel + panel / 2 - scale * (b[0] + b[1]) / 2;
        const w0 = this.cloth.height / 2 + scale * (b[2] + b[3]) / 2;
        const at = (q) => [u0 + scale * xy[2 * q], w0 - scale * xy[2 * q + 1]];
        c.strokeStyle = palette[k % palette.length];
        c.lineWidth = 1;
        c.beginPath();
        for (let i = 0; i < M; ++i)
          for (let j = 0; j < N; ++j) {
            const q = i * N + j;
            const [a0, a1] = at(q);
            if (j + 1 < N) { const [b0, b1] = at(q + 1); c.moveTo(a0, a1); c.lineTo(b0, b1); }
            if (i + 1 < M) { const [b0, b1] = at(q + N); c.moveTo(a0, a1); c.lineTo(b0, b1); }
          }
        c.stroke();
        const item = element("span", {style: "color:" + palette[k % palette.length]}, "\u25A0 " + r.method + "  ");
        this.legend.appendChild(item);
      });
    }

    drawEnergy() {
      const c = this.plot.getContext("2d");
      const W = this.plot.width, H = this.plot.height, left = 70, bottom = 18;
      c.clearRect(0, 0, W, H);
      let tMax = 0, eMin = Infinity, eMax = -Infinity;
      for (const r of this.runs) {
        tMax = Math.max(tMax, r.run.totalSteps() > 0 ? r.run.dt() * r.run.totalSteps() : 0);
        for (const [, e] of r.energy) { eMin = Math.min(eMin, e); eMax = Math.max(eMax, e); }
      }
      if (!(eMax > eMin)) { eMin -= 1; eMax += 1; }
      c.strokeStyle = "#888";
      c.strokeRect(left, 2, W - left - 2, H - bottom - 2);
      c.fillStyle = "#333";
      c.font = "11px sans-serif";
      c.fillText(eMax.toPrecision(4) + " J", 2, 12);
      c.fillText(eMin.toPrecision(4) + " J", 2, H - bottom);
      c.fillText("total energy over t in [0, " + tMax.toPrecision(3) + " s]", left + 4, H - 4);
      const sx = (t) => left + (W - left - 2) * t / (tMax || 1);
      const sy = (e) => 2 + (H - bottom - 4) * (1 - (e - eMin) / (eMax - eMin));
      this.runs.forEach((r, k) => {
        c.strokeStyle = palette[k % palette.length];
        c.beginPath();
        const stride = Math.max(1, Math.floor(r.energy.length / (2 * W)));
        for (let s = 0; s < r.energy.length; s += stride) {
          const [t, e] = r.energy[s];
          if (s === 0) c.moveTo(sx(t), sy(e)); else c.lineTo(sx(t), sy(e));
        }
        c.stroke();
      });
    }
  }

  // Where a demo cannot run, a note in its place; the page reads on without it.
  function note(root, text) {
    root.textContent = "";
    root.appendChild(element("p", {class: "cloth-demo-note"}, text));
  }

  function outputElement(id, parent) {
    let e = document.getElementById(id);
    if (!e) {
      e = element("pre", {id: id, class: "cloth-demo-output"});
      parent.appendChild(e);
    }
    return e;
  }

  function start() {
    const roots = document.querySelectorAll(".cloth-demo");
    if (roots.length === 0) return;
    const url = urlSettings();
    loadModule().then((module) => {
      roots.forEach((root, k) => {
        let demo;
        try {
          demo = new Demo(root, module, url);
        } catch (e) {
          note(root, "The live demo failed to start: " + e);
          if (url.autorun) outputElement("final-state", document.body).textContent = "error: " + e;
          return;
        }
        if (url.play && !url.autorun) demo.play();
        if (!url.autorun || k > 0) return;
        if (url.measure && demo.runs.length > 0)
          outputElement("step-cost", root).textContent = String(demo.runs[0].run.secondsPerStep());
        demo.finish();
        outputElement("run-status", root).textContent =
            demo.error || (demo.runs.length > 0 ? (demo.runs[0].run.stopMessage() || "ok") : "no run");
        outputElement("run-arguments", root).textContent = demo.runs.length > 0 ? demo.runs[0].args.join(" ") : "";
        outputElement("final-state", root).textContent =
            demo.runs.length > 0 ? demo.runs[0].run.finalState() : "error: " + demo.error;
      });
    }, (error) => {
      roots.forEach((root) => note(root,
          "This live demo runs the book's own code compiled to WebAssembly, which this copy of the book was built " +
          "without (the build makes it when Emscripten is installed). The text and figures above and below do not " +
          "depend on it."));
      if (url.autorun) outputElement("final-state", document.body).textContent = "error: " + error.message;
    });
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})();
