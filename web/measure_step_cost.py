#!/usr/bin/env python3
"""The cost of a step in the browser against the native program, and how far their states end apart: each run is
made by the native ch10_cloth and by the same flags in a demo page of the built book in headless Chromium
(`autorun&measure`: the module times the whole run with the native driver, simulate(), as run.txt's
wall_seconds / steps). For the cost each side runs `--repeat` times, alternated, and the fastest is kept (the
machine is shared). Writes the two tables the appendix "The book in the browser" includes, web/measured/
step_cost.md and web/measured/agreement.md (the largest difference of a coordinate at the end of runs of the
report cloth's fall, by method, step and end time), with the command, processor, compilers and browser that
measured them. Not run by CI: timings are quoted, never tested.

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

TIMED = [  # method, the flags of the run (the 20 x 20 report cloth), the page that runs it
    ("explicit_euler", "--K 50 --dt 0.001 --t-end 1", "ch02.html"),
    ("symplectic_euler", "--K 50 --dt 0.001 --t-end 1", "ch02.html"),
    ("rk4", "--K 200 --damping 20 --dt 0.002 --t-end 1", "ch03.html"),
    ("implicit_euler", "--K 200 --damping 20 --dt 0.01 --t-end 1", "ch04.html"),
]
# The agreement: the report cloth (K = 200, D = 20, falling at v0 = -20 m/s) by RK4 at two steps and by implicit
# Euler, ended at times on both sides of where its fall amplifies any difference.
AGREEMENT_TIMES = ["0.5", "0.6", "0.7", "0.8", "1"]
AGREEMENT = [("rk4", "--K 200 --damping 20 --dt 0.005", "ch03.html"),
             ("rk4", "--K 200 --damping 20 --dt 0.0025", "ch03.html"),
             ("implicit_euler", "--K 200 --damping 20 --dt 0.005", "ch04.html"),
             ("explicit_euler", "--K 50 --dt 0.005", "ch02.html")]


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
    cost = ["| method | run | steps | native [us/step] | WebAssembly in Chromium [us/step] | ratio |",
            "|---|---|---:|---:|---:|---:|"]
    agreement = ["| method | run | " + " | ".join(f"T = {t} s" for t in AGREEMENT_TIMES) + " |",
                 "|---|---|" + "---:|" * len(AGREEMENT_TIMES)]
    with tempfile.TemporaryDirectory() as work:
        for method, flags, page in TIMED:
            best_native = best_browser = float("inf")
            for _ in range(args.repeat):
                seconds, _, arguments = browser(args.html, page, method, flags.split(), work + "/profile")
                best_browser = min(best_browser, seconds)
                seconds, _, steps = native(program, arguments, work + "/native")
                best_native = min(best_native, seconds)
            cost.append(f"| `{method}` | `{flags}` | {steps} | {best_native * 1e6:.1f} | {best_browser * 1e6:.1f} | "
                        f"{best_browser / best_native:.1f} |")
        for method, flags, page in AGREEMENT:
            gaps = []
            for t in AGREEMENT_TIMES:
                _, web_state, arguments = browser(args.html, page, method, (flags + " --t-end " + t).split(),
                                                  work + "/profile")
                _, native_state, _ = native(program, arguments, work + "/native")
                gaps.append(f"{gap(web_state, native_state):.1e}")
            agreement.append(f"| `{method}` | `{flags}` | " + " | ".join(gaps) + " |")
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    chromium = subprocess.run(["chromium", "--version"], capture_output=True, text=True).stdout.strip()
    emcc = subprocess.run(["emcc", "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    emscripten = "Emscripten " + (re.findall(r"\) ([0-9.]+)", emcc) or ["?"])[0]
    # Code in backticks, as the programs' fragments write it (src/program/fragment.cpp): Doxygen would print the
    # dashes of a flag inside an HTML <code> as an en dash.
    provenance = (f'<div class="measured">Measured by `web/measure_step_cost.py --repeat {args.repeat}` on '
                  f"{html.escape(cpu)}, {platform.system()}: native `ch10_cloth` of the book's build, compiled by "
                  f"GCC with `-O3 -march=native -mno-avx512f -ffp-contract=off -fno-math-errno` (AVX2, FMA); "
                  f"WebAssembly by {emscripten} `-O3` in {html.escape(chromium)}.")
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "measured")
    os.makedirs(folder, exist_ok=True)
    tables = {
        "step_cost.md": cost + ["", provenance + f" Fastest of {args.repeat} runs a side, alternated, on a machine "
                                "shared with other work: the ratios are indicative.</div>"],
        "agreement.md": agreement + ["", provenance + " The largest difference of a coordinate between the "
                                     "browser's and the native final state [m].</div>"],
    }
    for name, lines in tables.items():
        with open(os.path.join(folder, name), "w") as f:
            f.write("\n".join(lines) + "\n")
        print("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
