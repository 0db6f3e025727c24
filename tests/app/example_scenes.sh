#!/usr/bin/env bash
# The shipped example skins end to end: scenes/fingertip.json (ellipsoidal cap), scenes/dome_stl.json (binary
# STL dome, regenerated here by scenes/make_dome_stl.py and compared byte for byte) and scenes/ridged_layer.json
# (fingerprint ridges over the sensor) through mesh, solve, green and kfit, contact and defect where the scene
# has them, at coarse settings (skin mesh sizes doubled; ridges at 5 elements per period on a smaller patch).
# Independent checks: the meshed volume against the skin's volume computed here (the ellipsoid by quadrature,
# the dome by the divergence theorem over the STL's facets), the thickness above each sensor against the
# closed-form top, and each command's second-method check (reciprocity, statics, condensed vs reaction
# readings) at round-off.
set -u
skinfem=$1
root=$(cd "$(dirname "$0")/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

/usr/bin/python3 "$root/scenes/make_dome_stl.py" "$tmp/dome.stl"
if ! cmp -s "$tmp/dome.stl" "$root/scenes/dome.stl"; then
  echo "FAIL scenes/dome.stl is not what scenes/make_dome_stl.py writes"
  exit 1
fi

fail=0
for name in fingertip dome_stl ridged_layer; do
  # Coarse settings: the skin's mesh sizes doubled, a sparser calibration scan and sweep.
  /usr/bin/python3 - "$root/scenes/$name.json" "$tmp/$name.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
m = s["mesh"]
for key in ("h_min", "h_max"):
    m[key] *= 2
s["calibration"]["spacing"] = 0.2
c = s.get("contact")
if c and "sweep" in c:  # contact.h stays: the contact must stay one element inside its zone
    c["sweep"]["positions"] = 5
r = s["geometry"].get("ridges")
if r:
    r["h"], r["radius"] = r["period"] / 5, 2 * r["period"]
json.dump(s, open(sys.argv[2], "w"))
PY
  commands="mesh solve green kfit"
  grep -q '"contact"' "$tmp/$name.json" && commands="$commands contact"
  grep -q '"sweep"' "$tmp/$name.json" && commands="$commands defect"
  for cmd in $commands; do
    extra=()
    # The defect's error-bar levels are tested on the default scene (defect_default.sh) and for determinism.
    [ "$cmd" = defect ] && extra=(--no-error-bars)
    if ! "$skinfem" "$cmd" "$tmp/$name.json" "${extra[@]}" --out "$tmp/$name/$cmd" >"$tmp/stdout" 2>"$tmp/err"; then
      echo "FAIL $cmd $name:"
      cat "$tmp/err"
      fail=1
    fi
  done
done
[ $fail -eq 0 ] || exit 1

/usr/bin/python3 - "$tmp" "$root/scenes" <<'PY'
import json, math, os, struct, sys
import numpy as np

tmp, scenes = sys.argv[1], sys.argv[2]
bad = []


def load(name, cmd, file="summary.json"):
    return json.load(open(os.path.join(tmp, name, cmd, file)))


def check_round_off(name):
    """Each command's own second method agrees at round-off (1e-10: far above 1e-15, far below any error)."""
    pairs = [("solve", "base_force_balance_rel"), ("solve", "residual"), ("green", "reciprocity_check_rel"),
             ("green", "max_adjoint_residual"), ("contact", "readings_condensed_vs_reactions_rel"),
             ("contact", "complementarity")]
    for cmd, key in pairs:
        v = load(name, cmd)[key]
        if not (math.isfinite(v) and abs(v) < 1e-10):
            bad.append(f"{name} {cmd} {key} = {v}")
    k = load(name, "kfit", "kfit.json")
    for s in k["sensors"]:
        if not all(math.isfinite(s[q]) for q in ("k_central", "k_lsq_line")):
            bad.append(f"{name} kfit sensor {s['sensor']}: k not finite")
    c = load(name, "contact")
    if not (c["contact_radius_mm"] > 0 and abs(c["force_N"] - json.load(open(os.path.join(tmp, name + ".json")))
                                                 ["contact"]["force"]) < 1e-9):
        bad.append(f"{name} contact: radius {c['contact_radius_mm']}, force {c['force_N']}")


def check_volume(name, exact, tol, why):
    v = load(name, "mesh")["volume_mm3"]
    print(f"{name}: meshed volume {v:.6f} mm3 against {exact:.6f} ({why}): {(v / exact - 1):+.2e}")
    if abs(v / exact - 1) > tol:
        bad.append(f"{name}: meshed volume {v} is more than {tol:g} from {exact}")


def check_thickness(name, top, tol, why):
    sensors = json.load(open(os.path.join(tmp, name + ".json")))["sensors"]
    line = sensors.get("line")
    at = lambda i: ([line["start"][k] + (i - 1) * line["step"][k] for k in range(2)] if line  # count from 1
                    else sensors["positions"][i - 1])
    for cmd, file in (("kfit", "kfit.json"), ("green", "summary.json")):
        for s in load(name, cmd, file)["sensors"]:
            h, want = s["h_mm"], top(*at(s["sensor"]))
            if abs(h - want) > tol:
                bad.append(f"{name} {cmd} sensor {s['sensor']}: thickness {h} mm, expected {want} ({why})")


# Fingertip: z = h - c + c sqrt(1 - (x/a)^2 - (y/b)^2), c = sqrt(R R_y), a = sqrt(R c), b = sqrt(R_y c).
g = json.load(open(os.path.join(scenes, "fingertip.json")))["geometry"]
R, Ry, h, rt = g["R"], g["R_y"], g["h"], g["truncation_radius"]
c = math.sqrt(R * Ry)
a, b = math.sqrt(R * c), math.sqrt(Ry * c)
top = lambda x, y: h - c + c * math.sqrt(1 - ((x - g["apex"][0]) / a) ** 2 - ((y - g["apex"][1]) / b) ** 2)
# Volume over the truncation disc: Gauss-Legendre (64) in r, trapezoid (512) in the angle (periodic, spectral).
r, w = np.polynomial.legendre.leggauss(64)
r, w = 0.5 * rt * (r + 1), 0.5 * rt * w
t = 2 * math.pi * np.arange(512) / 512
X, Y = np.outer(r, np.cos(t)), np.outer(r, np.sin(t))
Z = h - c + c * np.sqrt(1 - (X / a) ** 2 - (Y / b) ** 2)
volume = float((Z * (w * r)[:, None]).sum() * 2 * math.pi / 512)
# P2 geometry error O(h^4): 7e-6 at the scene's own sizes (mesh summary), 16 x that at twice the sizes.
check_volume("fingertip", volume, 2e-4, "quadrature of the ellipsoid")
check_thickness("fingertip", top, 1e-9, "the ellipsoid's top")

# Dome: the STL's enclosed volume by the divergence theorem (sum of signed tetrahedra to the origin); the
# mesh keeps the facets (a flat P2 tet is exact), so only round-off separates them.
data = open(os.path.join(scenes, "dome.stl"), "rb").read()
n = struct.unpack_from("<I", data, 80)[0]
facets = [np.array(struct.unpack_from("<12f", data, 84 + 50 * i)[3:], dtype=float).reshape(3, 3) for i in range(n)]
volume = sum(float(np.dot(f[0], np.cross(f[1], f[2]))) / 6 for f in facets)
check_volume("dome_stl", volume, 1e-9, "divergence theorem over the STL")


def faceted_top(x, y):
    """The STL's top above (x, y): linear interpolation on the upward facet that holds the point."""
    for f in facets:
        (ax, ay, az), (bx, by, bz), (cx, cy, cz) = f
        det = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay)
        if det <= 0:  # not an upward facet
            continue
        u = ((x - ax) * (cy - ay) - (cx - ax) * (y - ay)) / det
        v = ((bx - ax) * (y - ay) - (x - ax) * (by - ay)) / det
        if u >= -1e-12 and v >= -1e-12 and u + v <= 1 + 1e-12:
            return az + u * (bz - az) + v * (cz - az)
    raise ValueError(f"no top facet above ({x}, {y})")


# float32 coordinates (relative 6e-8 of 10 mm) bound the round-off.
check_thickness("dome_stl", faceted_top, 1e-5, "the STL's facets")
# Ridged layer: the flat box plus the ridges' volume, here by the midpoint rule on a 2000² grid over the
# patch (the C++ side integrates them as a Bessel integral); thickness is the mean one, h.
sc = json.load(open(os.path.join(tmp, "ridged_layer.json")))
g = sc["geometry"]
r = g["ridges"]
n = 2000
u = (np.arange(n) + 0.5) / n * 2 * r["radius"] - r["radius"]
X, Y = np.meshgrid(u, u)
rho = np.hypot(X, Y)
L, R = r["period"], r["radius"]
w = np.where(rho <= R - L, 1.0, np.where(rho < R, 0.5 * (1 + np.cos(np.pi * (rho - (R - L)) / L)), 0.0))
th = math.radians(r.get("angle_deg", 0.0))
ridge = 0.5 * r["height"] * w * np.cos(2 * math.pi * (X * math.cos(th) + Y * math.sin(th)) / L)
volume = (2 * g["half_width"]) ** 2 * g["h"] + float(ridge.sum()) * (2 * R / n) ** 2
# Mesh: P2 on the ridges (tests/mesh/test_build.cpp: 4e-6 at 5 elements per period); grid: O(1e-7) of it.
check_volume("ridged_layer", volume, 1e-5, "flat box + ridges by the midpoint rule")
check_thickness("ridged_layer", lambda x, y: g["h"], 1e-12, "the mean thickness")

for name in ("fingertip", "dome_stl"):
    check_round_off(name)
for cmd, key in (("solve", "base_force_balance_rel"), ("green", "reciprocity_check_rel")):
    v = load("ridged_layer", cmd)[key]
    if not (math.isfinite(v) and abs(v) < 1e-10):
        bad.append(f"ridged_layer {cmd} {key} = {v}")
d = load("fingertip", "defect")
if d.get("positions") != 5: bad.append(f"fingertip defect: {d.get('positions')} positions, expected 5")
for b_ in bad:
    print("FAIL", b_)
sys.exit(1 if bad else 0)
PY
