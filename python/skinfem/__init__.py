"""skinfem: finite-element verification of tactile sensors under an incompressible skin (mm, N, MPa).

The same pipeline as the ``skinfem`` command, with results as objects holding numbers and numpy arrays:

    import skinfem
    scene = skinfem.scene("scenes/flat_layer.json")       # a path, a JSON string or a dict
    fit = skinfem.kfit(scene)                              # the k correction of every sensor
    print(fit.sensors[0].k_central, fit.verdict)
    fit.to_dict()                                          # what `skinfem kfit` writes as kfit.json
    c = skinfem.contact(skinfem.scene("scenes/hertz_layer.json"))
    print(c.contact_radius_mm, c.p0_kPa, c.readings_kPa)   # c.to_dict(): `skinfem contact`'s summary.json
    d = skinfem.defect(skinfem.scene("scenes/candelier2011.json"))
    d.u_mm, d.varsigma_kPa("sliding")                      # positions; positions × sensors × (z, x)
    g = skinfem.greens(scene)                              # every sensor's Green maps (3D or meridian)
    g.g_per_mm2(0, [0.0, 1.0], [0.0, 0.0])                 # offsets × (zz, zx, xz, xx), 1/mm²
    g.kernel(0.1)                                          # on a grid over the top, as `skinfem green --grid`

The paper's model, one ingredient at a time: a Green tensor (halfspace_kernel, layer_kernel, fe_kernel), a
traction field (hertz_tractions: half-space or exact-layer pressure, friction ratio, shear strength), and
convolve (eq. (1)) or first_order_hole (eqs. (2)–(3)); crosscheck(scene) runs the report's comparison of
every variant against full FE.

Bad input raises skinfem.SceneError or MeshError (ValueErrors) with the command's one-line message; a
failed solve raises skinfem.SolverError (a RuntimeError).
"""
import json as _json
import os as _os

from ._skinfem import *  # noqa: F401,F403
from ._skinfem import (SceneError, _contact, _contact_json, _defect, _defect_json, _kfit_json,
                       _meridian_contact_json, load_scene, parse_scene)
from ._skinfem import greens as _greens
from ._skinfem import _skinfem_version as __version__


def scene(source, name_of_source=""):
    """A Scene from a JSON file path, a JSON text or a dict (relative paths inside resolve against the file's
    folder, or the current one)."""
    if isinstance(source, dict):
        return parse_scene(_json.dumps(source), name_of_source or _os.path.join(_os.getcwd(), "<dict>"))
    if isinstance(source, (str, _os.PathLike)) and _os.path.exists(source):
        return load_scene(_os.fspath(source))
    if isinstance(source, str) and source.lstrip().startswith("{"):
        return parse_scene(source, name_of_source or _os.path.join(_os.getcwd(), "<text>"))
    raise SceneError(f"scene: {source!r} is neither an existing file, a JSON object text nor a dict")


def _kfit_to_dict(self):
    """The result as `skinfem kfit` writes it (kfit.json)."""
    return _json.loads(_kfit_json(self))


KfitResult.to_dict = _kfit_to_dict  # noqa: F405


def contact(scene, friction="", path="auto"):
    """The scene's indenter on the skin, solved in every friction mode (what `skinfem contact` computes);
    attributes are those of `friction` ("none", "static", "uncoupled", "coupled"; default the scene's).
    path "auto" (the meridian where every reported mode is exact there), "3d" or "meridian": a ContactRun
    (3D) or a MeridianContactRun (its multipliers at multiplier_r_mm, the modes it left out in left_out)."""
    run = _contact(scene, friction, path)
    run._scene = scene
    return run


def _contact_to_dict(self):
    """The result as `skinfem contact` writes it (summary.json)."""
    return _json.loads(_contact_json(self, self._scene))


def _meridian_contact_to_dict(self):
    """The result as `skinfem contact` writes it on the meridian (summary.json)."""
    return _json.loads(_meridian_contact_json(self, self._scene))


ContactRun.to_dict = _contact_to_dict  # noqa: F405
MeridianContactRun.to_dict = _meridian_contact_to_dict  # noqa: F405


def defect(scene, error_scales=(2.0, 1.41)):
    """A hole swept along the scene's contact.sweep, static and sliding (what `skinfem defect` computes),
    and the largest sliding signal on coarser levels (every mesh size x s) for its error bar; () for none."""
    run = _defect(scene, list(error_scales))
    run._scene = scene
    return run


def _defect_to_dict(self):
    """The result as `skinfem defect` writes it (summary.json)."""
    return _json.loads(_defect_json(self, self._scene))


DefectRun.to_dict = _defect_to_dict  # noqa: F405


def greens(scene, path="auto"):
    """Every sensor's Green maps (what `skinfem green` computes): path "auto" (the meridian where the skin
    allows), "3d" or "meridian"."""
    g = _greens(scene, path)
    g._scene = scene
    return g


def _kernel(self, dx_mm, box_mm=None):
    """Every sensor's disc-reading maps on a grid of spacing dx_mm over box_mm = (x_lo, x_hi, y_lo, y_hi)
    (default: the skin's footprint, as `skinfem green --grid`): dict of x_mm, y_mm, on_skin (ny × nx) and
    g_per_mm2 (sensors × (zz, zx, xz, xx) × ny × nx)."""
    return self._kernel_grid(self._scene, dx_mm, box_mm)


Greens.kernel = _kernel  # noqa: F405
