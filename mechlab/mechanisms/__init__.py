"""Every mechanism class, one module per family, each a frozen dataclass of its dimensions.

A mechanism's ``motion(phi)`` takes crank angles (radians, scalar or array) and returns
its :class:`~mechlab.motion.Motion`: every joint's path with its first and second
analogs, and the output law.
"""

from .antiparallelogram import Antiparallelogram
from .base import Mechanism
from .cam import CamUndercutError, OscillatingRollerCam, TranslatingRollerCam
from .curved_slot import CircleSlot, CurvedSlotLink, ParametricSlot, SampledSlot, TranslatingCurvedSlot
from .fourbar import FourBar, Grashof
from .geneva import ExternalGeneva, InternalGeneva
from .lambda_mechanism import LambdaMechanism
from .lambda_sixbars import LambdaRockerSixBar, LambdaSlottedSixBar
from .lambda_sliders import LambdaSliderSixBar, LambdaTranslatingSlot
from .sixbar_iv import SixBarIV
from .slider_crank import SliderCrank
from .slotted import SineMechanism, SlottedLink
from .spherical_geneva import SphericalGeneva
from .trammel import EllipticTrammel

__all__ = [
    "Antiparallelogram",
    "CamUndercutError",
    "CircleSlot",
    "CurvedSlotLink",
    "EllipticTrammel",
    "ExternalGeneva",
    "FourBar",
    "Grashof",
    "InternalGeneva",
    "LambdaMechanism",
    "LambdaRockerSixBar",
    "LambdaSliderSixBar",
    "LambdaSlottedSixBar",
    "LambdaTranslatingSlot",
    "Mechanism",
    "OscillatingRollerCam",
    "ParametricSlot",
    "SampledSlot",
    "SineMechanism",
    "SixBarIV",
    "SliderCrank",
    "SlottedLink",
    "SphericalGeneva",
    "TranslatingCurvedSlot",
    "TranslatingRollerCam",
]
