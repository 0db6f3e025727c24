#!/usr/bin/env python3
"""Detectability against the physics: the smallest hole the array and its best sensor detect
(`skinfem perceive`, docs/perception.md) on variants of the default scene.

Variants: the scene as shipped (discs, Coulomb mu = 3); a shear strength instead of Coulomb; post sensors
(200 um x 400 um, rigid); a thinner (2 mm) and a thicker (4 mm) skin. Each at the paper's noise (0.6 and
0.4 kPa), N = 14 passages, samples every sweep step (0.033 mm), p_fa 1 %, p_d 90 %.

    $ /usr/bin/python3 bench/perception_map.py build/app/skinfem out/perception_map
    discs_coulomb   static: array 0.353 mm, one sensor 0.449 mm; sliding: ...

Writes OUT/perception_map.csv (variant,case,array_snr,array_min_mm,sensor_min_mm,dofs,seconds; a bound is
written as <0.0625 or >0.5). Each variant is a fresh process: 13 s for discs, about a minute for posts.
"""
import csv
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def variants(base):
    def v(change):
        s = json.loads(json.dumps(base))
        change(s)
        return s

    def shear(s):
        s["contact"]["friction"]["law"] = "shear_strength"

    def posts(s):
        s["sensors"]["model"] = "post"
        s["sensors"]["post"] = {"diameter": 0.2, "height": 0.4, "support": "rigid"}
        del s["sensors"]["disc_diameter"]

    def thickness(h):
        def f(s):
            s["geometry"]["h"] = h
        return f

    return {"discs_coulomb": v(lambda s: None), "discs_shear_strength": v(shear), "posts_coulomb": v(posts),
            "discs_h2": v(thickness(2.0)), "discs_h4": v(thickness(4.0))}


def bound(b):
    return f"{b['mm']:.3f}" if "mm" in b else (f"<{b['below_mm']:.4g}" if "below_mm" in b else f">{b['above_mm']:.4g}")


def main():
    skinfem, out = sys.argv[1], sys.argv[2]
    os.makedirs(out, exist_ok=True)
    base = json.load(open(os.path.join(HERE, "..", "scenes", "candelier2011.json")))
    rows = []
    for name, scene in variants(base).items():
        scene["name"] = name
        path = os.path.join(out, name + ".json")
        json.dump(scene, open(path, "w"), indent=1)
        run = os.path.join(out, name)
        subprocess.run([skinfem, "perceive", path, "--out", run], check=True, stdout=subprocess.DEVNULL,
                       env=dict(os.environ, OPENBLAS_NUM_THREADS="1"))
        j = json.load(open(os.path.join(run, "perception.json")))
        line = name
        for case in ["static", "sliding"]:
            k = j["cases"][case]
            a, s = bound(k["smallest_detected_array"]), bound(k["smallest_detected_best_sensor"])
            rows.append([name, case, k["array_snr"], a, s, j["dofs"], j["wall_total_s"]])
            line += f"  {case}: array {a} mm, one sensor {s} mm (SNR {k['array_snr']:.2f})"
        print(line, flush=True)
    with open(os.path.join(out, "perception_map.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["variant", "case", "array_snr", "array_min_mm", "sensor_min_mm", "dofs", "seconds"])
        w.writerows(rows)


if __name__ == "__main__":
    main()
