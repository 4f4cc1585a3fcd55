"""The version of pipflow, in a module of its own so that any module can read it without
importing the package face (whose lazy names load the engine and the bench)."""

__version__ = "0.1.0"
