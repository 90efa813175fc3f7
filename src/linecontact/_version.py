"""The version of linecontact (one place; read by the build backend and the package)."""

__version__ = "0.2.0"
