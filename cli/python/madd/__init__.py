"""madd: Medial Axis Domain Decomposition and parallel quality meshing in 2D."""
from ._madd import *  # noqa: F401,F403
from ._madd import __version__  # noqa: F401
