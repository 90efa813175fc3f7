"""linecontact: adhesive contact mechanics of a cylinder on an elastic substrate."""

__version__ = "0.1.0"
