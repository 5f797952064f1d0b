"""Build your own linkage: a crank and Assur groups attached to named joints (:class:`Linkage`), the
groups RRR, RRP, RPR, PRP, RPP with their solvers, the class-IV Tetrad, a pin in a CurvedSlot and a
CamFollower (solved by continuation), guides and points fixed on links; a family of linkages
(:class:`LinkageFamily`) is a dataclass of dimensions that builds one."""

from .built import Linkage, LinkageFamily
from .closure import CamFollower, CurvedSlot, Tetrad
from .groups import PRP, RPP, RPR, RRP, RRR, Crank, Guide, Point

__all__ = ["PRP", "RPP", "RPR", "RRP", "RRR", "CamFollower", "Crank", "CurvedSlot", "Guide", "Linkage",
           "LinkageFamily", "Point", "Tetrad"]
