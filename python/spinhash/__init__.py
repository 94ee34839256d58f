"""spinhash: 3D object recognition in airborne lidar point clouds (spin images,
LSH, batch RANSAC). See docs/python.md.

The package sits over the compiled extension ``spinhash._spinhash`` (numpy
clouds, databases, recognisers, scenes); ``spinhash.survey`` runs a whole
survey of tiles on Dask (docs/survey.md)."""
from ._spinhash import *  # noqa: F401,F403  (Database, Recognizer, SceneRecognizer, read_cloud, ...)
from ._spinhash import __version__  # noqa: F401
