"""From requirements to a mechanism: dwell slots, lambda guiding, the six-bars on it, dwell six-bars from any
four-bar's coupler curve (:mod:`.coupler_dwell`), Geneva tables.

Each module takes what the designer asks for (a dwell, a time ratio, a swing, a stroke)
and returns a mechanism of :mod:`mechlab.mechanisms`, or a named refusal.
"""
