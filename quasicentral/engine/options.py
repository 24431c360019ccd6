"""The checker's settings: every threshold it uses is named here, once."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Options:
    """The checker's settings; every threshold it uses is named here."""

    dps: int = 30  # first rung of the ladder; the second is 2 × dps
    points: int = 20  # in-domain points per claim
    integral_points: int = 12  # per claim with an integral (a quadrature costs ~100× a closed form)
    confirm_points: int = 4  # points evaluated on every rung even where the first rung agrees
    symbolic_seconds: float = 3.0
    # the same bound for an entry checked as it stands (identity mode: a formula collection's),
    # where the numbers decide nearly every entry and sympy proves next to none of them (DLMF's
    # special functions are opaque to it): 3 s per failed proof would cost both DLMF chapters
    # most of an hour
    identity_symbolic_seconds: float = 0.3
    symbolic: bool = True
    certify: bool = True
    # integrand evaluations one witness ball may spend (~30 µs each at 200 bits): past this
    # its ball integral gives up and the value stays uncertified.  Counted, not timed, so that
    # a report's certified digits are the same on every machine
    certify_evaluations: int = 10_000
    agreement_exponent: float = 0.6  # agreement: |p − d| ≤ 10^(−0.6·dps)·scale on each rung
    stable_within: float = 1e-3  # a difference is real when it changes by less than this between rungs
    # a difference that falls by 10^(−0.8·Δdps) or more from the first rung to the last, and as
    # much again on a rung as far beyond, is the rounding of an exact zero (cn(K, k) = 0: the
    # argument K itself is rounded), not a value
    vanishing_exponent: float = 0.8
    scale_floor: float = 1e-6  # the scale is at least this fraction of the median magnitude
    early_stop_after: int = 6  # points evaluated before a refutation may stop the run early ...
    early_stop_disagreements: int = 3  # ... once this many of them disagree for good
    remembered_values: int = 50_000  # derived values kept for an erratum's second comparison
    # False: a dimensionally inconsistent relation is refuted on its dimensions alone, without
    # the numbers (and so without a witness) — it is refuted whatever they say
    numbers_after_dimensions: bool = True
    # the wall-clock ceiling of one entry's check, seconds (its derivation, comparison and
    # numbers together); past it the entry is inconclusive, never a hang.  The CPU-time
    # budget of the same work is the same number of seconds
    timeout: float = 120.0

    MIN_DPS = 15  # below, the agreement tolerance 10^(−0.6·dps) would be too loose to mean anything

    def __post_init__(self):
        if self.dps < self.MIN_DPS:
            raise ValueError(f"the precision ladder starts at {self.MIN_DPS} digits or more, not {self.dps}")

    @property
    def ladder(self) -> tuple[int, ...]:
        return (self.dps, 2 * self.dps)

    def cache_key(self) -> dict:
        """The settings a verdict depends on (the timeout bounds the work, it does not change a
        verdict that finishes in time: not part of the key)."""
        from dataclasses import asdict

        d = asdict(self)
        d.pop("timeout")
        return d
