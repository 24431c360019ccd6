"""The notation: symbols, dimensions, domains and the one sympy → numbers bridge."""
