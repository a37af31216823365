#!/usr/bin/env python3
"""The cost of a step in the browser against the native program, and how far their states end apart: each run of
the table is made by the native ch10_cloth and by the same flags in a demo page of the built book in headless
Chromium (`autorun&measure`: the module times the whole run with the native driver, simulate(), as run.txt's
wall_seconds / steps). Each side runs `--repeat` times, alternated, and the fastest is kept (the machine is
shared). Writes web/measured/step_cost.md, the table the appendix "The book in the browser" includes, with the
command, processor, compilers and browser that measured it. Not run by CI: timings are quoted, never tested.

    web/measure_step_cost.py [--html build/docs/html] [--bin build/bin] [--repeat 5]
"""
import argparse
import html
import os
import platform
import re
import shlex
import subprocess
import sys
import tempfile

RUNS = [  # method, the flags of the run (20 x 20 report cloth unless said), the page that runs it
    ("explicit_euler", "--K 50 --dt 0.01 --t-end 1", "ch02.html"),
    ("rk4", "--K 200 --damping 20 --dt 0.005 --t-end 1", "ch03.html"),
    ("implicit_euler", "--K 200 --damping 20 --dt 0.05 --t-end 1", "ch04.html"),
]


def browser(html_dir, page, method, flags, profile):
    query = "&".join(f"{flag[2:]}={value}" for flag, value in zip(flags[::2], flags[1::2]))
    url = f"file://{os.path.abspath(html_dir)}/{page}?method={method}&{query}&autorun&measure"
    dom = subprocess.run(["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                          "--disable-component-update", "--no-first-run", f"--user-data-dir={profile}",
                          "--dump-dom", url], capture_output=True, text=True, timeout=600).stdout

    def element(name):
        m = re.search(r'<pre id="' + name + r'"[^>]*>(.*?)</pre>', dom, re.S)
        if not m:
            sys.exit(f"measure_step_cost: {url} wrote no {name}")
        return html.unescape(m.group(1)).strip()
    return float(element("step-cost")), element("final-state"), element("run-arguments")


def native(program, arguments, out):
    subprocess.run([program, *shlex.split(arguments), "--out", out], check=True, capture_output=True)
    kv = dict(line.split(" = ", 1) for line in open(os.path.join(out, "run.txt")).read().splitlines() if " = " in line)
    return float(kv["wall_seconds"]) / float(kv["steps"]), open(os.path.join(out, "final.dat")).read(), int(kv["steps"])


def gap(a, b):
    rows = lambda text: [line.split() for line in text.splitlines() if line and not line.startswith("#")]
    return max(abs(float(x) - float(y)) for p, q in zip(rows(a), rows(b)) for x, y in zip(p[2:5], q[2:5]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--html", default="build/docs/html")
    parser.add_argument("--bin", default="build/bin")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    program = os.path.join(args.bin, "ch10_cloth")
    lines = ["| method | run | steps | native [us/step] | WebAssembly in Chromium [us/step] | ratio | "
             "largest gap in x [m] |", "|---|---|---:|---:|---:|---:|---:|"]
    with tempfile.TemporaryDirectory() as work:
        for method, flags, page in RUNS:
            best_native = best_browser = float("inf")
            for _ in range(args.repeat):
                cost, web_state, arguments = browser(args.html, page, method, flags.split(), work + "/profile")
                best_browser = min(best_browser, cost)
                cost, native_state, steps = native(program, arguments, work + "/native")
                best_native = min(best_native, cost)
            lines.append(f"| `{method}` | `{flags}` | {steps} | {best_native * 1e6:.1f} | {best_browser * 1e6:.1f} | "
                         f"{best_browser / best_native:.1f} | {gap(web_state, native_state):.2g} |")
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    chromium = subprocess.run(["chromium", "--version"], capture_output=True, text=True).stdout.strip()
    emcc = subprocess.run(["emcc", "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    lines.append("")
    lines.append(f'<div class="measured">Measured by <code>web/measure_step_cost.py --repeat {args.repeat}</code> '
                 f"(fastest of {args.repeat}, alternated) on {html.escape(cpu)}, {platform.system()}: native "
                 f"<code>ch10_cloth</code> of the book's build (<code>-O3 -march=native -ffp-contract=off</code>), "
                 f"WebAssembly by {html.escape(emcc.split('(')[0].strip())} (<code>-O3</code>) in "
                 f"{html.escape(chromium)}. The machine was shared with other work: the ratios are indicative."
                 f"</div>")
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "measured", "step_cost.md")
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
