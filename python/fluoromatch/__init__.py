"""fluoromatch: exact DRRs and 2D/3D registration of X-ray images to CT and meshes.

    import fluoromatch as fm
    ct = fm.read_volume("ct.nii.gz")              # any format the CLI reads
    g = fm.scene_geometry([0, 0, 0, 30, 10, 0], ct.center)
    image = fm.drr(ct, g)                          # (rows, cols) float32, exact line integrals

Conventions (docs/python.md): millimetres and degrees; volumes' arrays are (z, y, x) views of
the engine's values, spacing and origin (x, y, z); images (rows, cols); poses 4x4 float64
arrays named aFromB (worldFromObject unless a name says otherwise); errors are
fluoromatch.Error with the engine's message.
"""
from ._fluoromatch import *  # noqa: F401,F403  (the engine's functions and classes)
from ._fluoromatch import Error, __doc__ as _engine_doc  # noqa: F401

__all__ = [name for name in dir() if not name.startswith("_")]
