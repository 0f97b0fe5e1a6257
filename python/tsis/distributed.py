"""Many frames on many workers (docs/python.md)."""
