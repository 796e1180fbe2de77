"""Numbers printed in the paper (Kuznetsov), in one place, for comparisons in reports."""

__all__ = ["PAPER_EXPONENTS"]

#: Lyapunov exponents printed in section 2 (unit speed, equal masses), largest first.
PAPER_EXPONENTS = {3: (0.500,), 4: (0.385, 0.230), 5: (0.298, 0.227, 0.121)}
