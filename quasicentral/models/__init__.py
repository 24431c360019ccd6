"""The physical models and their evaluators (double, mpmath, balls)."""
