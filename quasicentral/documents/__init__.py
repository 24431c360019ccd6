"""Documents: the LaTeX printer, prose, reports and handouts."""
