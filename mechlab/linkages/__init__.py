"""One module per family of single-loop mechanisms, each a frozen dataclass."""

from .base import Mechanism
from .fourbar import FourBar, Grashof
from .slider_crank import SliderCrank
from .slotted import SineMechanism, SlottedLink

__all__ = ["Mechanism", "FourBar", "Grashof", "SliderCrank", "SlottedLink", "SineMechanism"]
