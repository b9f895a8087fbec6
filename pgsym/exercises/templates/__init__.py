"""The built-in exercise templates, grouped by the part of the book they practise."""

from __future__ import annotations

from .line1 import CrossRatioTemplate
from .metric import AngleTemplate, ConicTypeTemplate, PerpendicularTemplate
from .plane import HomogeneousTemplate, IdealPointTemplate, IncidenceTemplate, JoinTemplate, MeetTemplate
from .space import PlaneThroughTemplate, PluckerTemplate, PointOnPlanesTemplate
from .transform import (
    ApplyConicTemplate,
    ApplyLineTemplate,
    ApplyPointTemplate,
    ClassifyTemplate,
    DecomposeTemplate,
    FourPointsTemplate,
    PreservedTemplate,
)

BUILTIN_TEMPLATES = (
    HomogeneousTemplate,
    JoinTemplate,
    MeetTemplate,
    IdealPointTemplate,
    IncidenceTemplate,
    ApplyPointTemplate,
    ApplyLineTemplate,
    ApplyConicTemplate,
    ClassifyTemplate,
    PreservedTemplate,
    CrossRatioTemplate,
    FourPointsTemplate,
    PlaneThroughTemplate,
    PointOnPlanesTemplate,
    PluckerTemplate,
    DecomposeTemplate,
    AngleTemplate,
    PerpendicularTemplate,
    ConicTypeTemplate,
)

__all__ = ["BUILTIN_TEMPLATES"]
