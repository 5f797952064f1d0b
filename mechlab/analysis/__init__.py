"""What a mechanism's motion tells: instantaneous centres and centrodes, the curved-slot
equivalence, half-turn relations, motion laws and their invariants, intermittency.
"""
