"""rbsim: rigid bodies for physically based animation coursework (docs/python.md).

The package holds the compiled module rbsim._rbsim (python/src) and re-exports every name of it,
so rbsim.World, rbsim.load_scene, rbsim.InputError and rbsim.__version__ are the module's own
(their __module__ is "rbsim"); its types are in __init__.pyi, with py.typed (PEP 561)."""
from ._rbsim import *  # noqa: F401,F403  every public name of the compiled module
from ._rbsim import __doc__, __version__  # noqa: F401

from . import _rbsim

_RENDERING = ("Renderer", "VideoWriter", "run")


def __getattr__(name):
    """A physics-only build (RBSIM_PYTHON_RENDER=OFF) has no Renderer, VideoWriter or run (the program's
    runner, which draws frames): say so, and how to get them."""
    if name in _RENDERING and not hasattr(_rbsim, name):
        raise AttributeError(f"rbsim.{name}: this rbsim was built physics-only (RBSIM_PYTHON_RENDER=OFF), without "
                             "the renderer; build it with RBSIM_PYTHON_RENDER=ON (docs/python.md, Install)")
    raise AttributeError(f"module 'rbsim' has no attribute '{name}'")
