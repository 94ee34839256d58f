"""spinhash: 3D object recognition in airborne lidar point clouds (spin images,
LSH, batch RANSAC). See docs/python.md.

The package sits over the compiled extension ``spinhash._spinhash`` (numpy
clouds, databases, recognisers, scenes); ``spinhash.survey`` runs a whole
survey of tiles on Dask (docs/survey.md)."""
try:
    import numpy  # noqa: F401  (every cloud goes in and out as a numpy array)
except ImportError as _missing:
    raise ImportError(
        "spinhash needs numpy, which this Python does not have: install it (Debian: apt-get install "
        "python3-numpy; or pip install numpy), or run the Python spinhash was built for") from _missing

from ._spinhash import *  # noqa: F401,F403  (Database, Recognizer, SceneRecognizer, read_cloud, ...)
from ._spinhash import __version__  # noqa: F401
