"""Numbers printed in the paper (Kuznetsov), in one place, for comparisons in reports."""

__all__ = ["PAPER_EXPONENTS", "EXPONENT_DECIMALS", "EQ22_DIGITS", "EQ22_DT"]

#: Lyapunov exponents printed in section 2 (unit speed, equal masses), largest first.
PAPER_EXPONENTS = {3: (0.500,), 4: (0.385, 0.230), 5: (0.298, 0.227, 0.121)}
#: Decimals to which section 2 prints them: each known to ± half a unit of the last.
EXPONENT_DECIMALS = 3

#: Section 3, after eq (22): route (a) (eqs 19–21) and eq (22) coincide "up to the fifth
#: significant digit" with the RK4 step Δt = 0.01.
EQ22_DIGITS = 5
EQ22_DT = 0.01
