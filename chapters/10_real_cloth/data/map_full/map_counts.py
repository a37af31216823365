#!/usr/bin/env python3
"""The counts Chapter 10 quotes from its measured map, recomputed from the part files beside this script (run by
hand; `ch10_map --tables` writes the tables, this checks the sentences about them).

A run reaches a level when it finished and its error over the frames (the largest distance of any particle from
the reference at any frame) is at most the level: 1 mm, 1 cm, or 5 % of the part's motion (plausible). A level is
won by the fastest such run of all the part's runs, the book's and the peers'. Explicit programs are those the
tables call so (map_parts.cpp): symplectic Euler, RK4, Dormand-Prince and odeint's RK4 and Dormand-Prince.
Single timings spread by about a quarter, so a lead under 1.25 is printed as a tie.

    python3 map_counts.py [DIR]
"""
import glob
import os
import shlex
import sys

EXPLICIT = {"symplectic_euler", "rk4", "dopri5", "odeint_rk4", "odeint_dopri5"}
TIE = 1.25


def read_part(path):
    with open(path) as f:
        words = f.readline()[2:].split()
        head = dict(zip(words[::2], words[1::2]))
        runs = []
        for line in f:
            if line.strip() and not line.startswith("#"):
                t = shlex.split(line)
                runs.append({"program": t[1], "setting": t[3], "seconds": float(t[5]), "error": float(t[7]),
                             "ok": t[8] == "ok"})
    return head["part"], float(head["T"]), float(head["motion_over_frames"]), runs


def fastest(runs, level, keep=lambda r: True):
    reached = [r for r in runs if keep(r) and r["ok"] and r["error"] <= level]
    return min(reached, key=lambda r: r["seconds"]) if reached else None


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    parts = sorted(read_part(p) for p in glob.glob(os.path.join(folder, "map_*.dat")))
    wins = {}
    for name, T, motion, runs in parts:
        for level_name, level in (("plausible", 0.05 * motion), ("1 cm", 1e-2), ("1 mm", 1e-3)):
            w = fastest(runs, level)
            kind = "explicit" if w["program"] in EXPLICIT else "implicit or position-based"
            wins.setdefault((level_name, kind), []).append(name)
            wins.setdefault((level_name, w["program"]), []).append(name)
            other = fastest(runs, level, lambda r: (r["program"] in EXPLICIT) != (w["program"] in EXPLICIT))
            se = fastest(runs, level, lambda r: r["program"] == "symplectic_euler")
            lead = other["seconds"] / w["seconds"] if other else float("inf")
            se_ratio = f"x{se['seconds'] / w['seconds']:.3g}" if se else "not reached"
            print(f"{name:15s} T {T:.1f} s, motion {motion:.3g} m, {level_name:9s}: {w['program']} {w['setting']}"
                  f" {w['seconds']:.3g} s ({1e3 * w['error']:.3g} mm); other kind x{lead:.3g}"
                  f"{' TIE' if lead < TIE else ''}; symplectic Euler {se_ratio}")
    for (level_name, who), names in sorted(wins.items()):
        print(f"{level_name:9s} {who:26s} {len(names):2d}: {' '.join(names)}")
    motions = [motion for _, _, motion, _ in parts]
    print(f"{len(parts)} parts; motion {min(motions):.3g} to {max(motions):.3g} m; 1 mm is 1/{min(motions) / 1e-3:.0f}"
          f" to 1/{max(motions) / 1e-3:.0f} of it, 1 cm at most {100 * 1e-2 / min(motions):.2g} %")


if __name__ == "__main__":
    main()
