"""High-precision cross-checks of the closed forms, and the scene simulator."""
