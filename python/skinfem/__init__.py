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

Bad input raises skinfem.SceneError or MeshError (ValueErrors) with the command's one-line message; a
failed solve raises skinfem.SolverError (a RuntimeError).
"""
import json as _json
import os as _os

from ._skinfem import *  # noqa: F401,F403
from ._skinfem import SceneError, _contact, _contact_json, _defect, _defect_json, _kfit_json, load_scene, parse_scene
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


def contact(scene, friction=""):
    """The scene's indenter on the skin, solved in every friction mode (what `skinfem contact` computes);
    attributes are those of `friction` ("none", "static", "uncoupled", "coupled"; default the scene's)."""
    run = _contact(scene, friction)
    run._scene = scene
    return run


def _contact_to_dict(self):
    """The result as `skinfem contact` writes it (summary.json)."""
    return _json.loads(_contact_json(self, self._scene))


ContactRun.to_dict = _contact_to_dict  # noqa: F405


def defect(scene):
    """A hole swept along the scene's contact.sweep, static and sliding (what `skinfem defect` computes)."""
    run = _defect(scene)
    run._scene = scene
    return run


def _defect_to_dict(self):
    """The result as `skinfem defect` writes it (summary.json)."""
    return _json.loads(_defect_json(self, self._scene))


DefectRun.to_dict = _defect_to_dict  # noqa: F405
