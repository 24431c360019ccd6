"""Jets: the motion's functions and their derivatives as plain symbols.

:func:`to_jets` replaces each function of the motion and each of its derivatives by a symbol
of its own (``x(t) → x_t0``, ``x'(t) → x_t1``, ``u(nu, T)``'s ∂²u/∂ν∂T → ``u_nu1_T1``): an
identity among derivatives holds for all motions exactly when it holds for all values of these
jets.  A :class:`Jet` knows the function and the orders it stands for.
"""

from __future__ import annotations

import sympy as sp


class Jet(sp.Symbol):
    """The value of ``function`` differentiated ``orders`` times in its variables, as one symbol
    (positive where the function is declared nonnegative and not differentiated; else real)."""

    def __new__(cls, function: sp.Basic, orders: tuple[int, ...]):
        variables = function.args
        if len(variables) == 1:
            name = f"{function.func.__name__}_{variables[0].name}{orders[0]}"
        else:
            name = function.func.__name__ + "".join(f"_{v.name}{k}" for v, k in zip(variables, orders))
        positive = not any(orders) and bool(function.is_nonnegative)
        obj = sp.Symbol.__xnew__(cls, name, **({"positive": True} if positive else {"real": True}))
        obj.function, obj.orders = function, tuple(orders)
        return obj

    def __getnewargs_ex__(self):
        return ((self.function, self.orders), {})

    def _hashable_content(self):
        return super()._hashable_content() + (self.function, self.orders)

    @property
    def order(self) -> int:
        """The total order of differentiation."""
        return sum(self.orders)


def _variables(f: sp.Basic) -> tuple | None:
    """The symbols an applied function is a function of (``x(t)`` → (t,)); None for other
    applications (x(0), u(nu, 2))."""
    if isinstance(f, sp.core.function.AppliedUndef) and f.args and all(isinstance(a, sp.Symbol) for a in f.args) \
            and len(set(f.args)) == len(f.args):
        return f.args
    return None


def to_jets(expr: sp.Basic) -> sp.Basic:
    """Evaluate derivatives of expressions, then name each function jet by a symbol."""
    if expr.has(sp.Derivative):
        expr = expr.replace(lambda e: isinstance(e, sp.Derivative), lambda e: e.doit())
    repl = {}
    for d in expr.atoms(sp.Derivative):
        variables = _variables(d.expr)
        if variables is not None and {v for v, _ in d.variable_count} <= set(variables):
            counts = dict()
            for v, k in d.variable_count:
                counts[v] = counts.get(v, 0) + int(k)
            repl[d] = Jet(d.expr, tuple(counts.get(v, 0) for v in variables))
    expr = expr.xreplace(repl)
    repl = {f: Jet(f, (0,) * len(f.args)) for f in expr.atoms(sp.core.function.AppliedUndef)
            if _variables(f) is not None}
    return expr.xreplace(repl)


def jet_symbol(f: sp.Basic, order: int) -> Jet:
    """The symbol standing for the ``order``-th derivative of a function of one variable."""
    return Jet(f, (order,))


def is_jet(sym: sp.Basic) -> bool:
    return isinstance(sym, Jet)


def jet_of(sym: Jet) -> tuple[sp.Basic, int]:
    """The function and (total) derivative order a jet symbol stands for."""
    return sym.function, sym.order
