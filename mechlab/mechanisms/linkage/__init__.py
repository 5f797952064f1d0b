"""Build your own linkage: a crank and Assur groups attached to named joints (:class:`Linkage`), the
groups RRR, RRP, RPR, PRP, RPP with their solvers, guides and points fixed on links; a family of linkages
(:class:`LinkageFamily`) is a dataclass of dimensions that builds one."""

from .built import Linkage, LinkageFamily
from .groups import PRP, RPP, RPR, RRP, RRR, Crank, Guide, Point

__all__ = ["PRP", "RPP", "RPR", "RRP", "RRR", "Crank", "Guide", "Linkage", "LinkageFamily", "Point"]
