"""The handbook's version (the package's own, as pyproject.toml gives it): what a design's JSON output carries."""
VERSION = "0.1.0"
