"""tribolab in Python: the friction and impact workflows of the `tribolab` command line as
functions returning dicts (the command's --json object) with numpy arrays beside it.

    import tribolab
    r = tribolab.incline.predict(mu=0.634, phi_deg=20.96, v0=2.62)

Modules: tribolab.incline (incline study, the disc on a rough incline), tribolab.bounce (rugby-ball study,
the spinning rugby ball), tribolab.track (tracked data). SI units; angles in degrees where a
name ends in _deg. Bad input raises ValueError with the command line's message; an unknown
keyword raises TypeError. See docs/python.md.
"""
from . import bounce, incline, track

__all__ = ["incline", "bounce", "track"]
__version__ = "0.1.0"
