"""Colours of the quality map: the scaled Jacobian of each quad as a colour.

Red at 0.2 and below (a quad that poor spoils the stresses around it), through yellow
at 0.6, to green at 1 (a square); inverted quads (below 0) purple, which the mesher
never writes unless told to. Pure functions, so the mapping is tested headless.
"""
from typing import Dict, Sequence, Tuple

Colour = Tuple[float, float, float]

INVERTED: Colour = (0.55, 0.0, 0.55)
_STOPS = ((0.2, (0.85, 0.0, 0.0)), (0.6, (0.95, 0.85, 0.0)), (1.0, (0.0, 0.65, 0.0)))


def quality_colour(scaled_jacobian: float) -> Colour:
    """quality_colour(): the colour of one quad's scaled Jacobian."""
    if scaled_jacobian < 0:
        return INVERTED
    if scaled_jacobian <= _STOPS[0][0]:
        return _STOPS[0][1]
    for (low, low_colour), (high, high_colour) in zip(_STOPS, _STOPS[1:]):
        if scaled_jacobian <= high:
            t = (scaled_jacobian - low) / (high - low)
            return tuple(a + t * (b - a) for a, b in zip(low_colour, high_colour))
    return _STOPS[-1][1]


def histogram_band_colour(band: int) -> Colour:
    """histogram_band_colour(): the colour of band k of tquad's jacobian_histogram
    (0: below 0, then the tenths of [0, 1]), at the band's middle."""
    return INVERTED if band == 0 else quality_colour((band - 1) / 10 + 0.05)


def element_colours(scaled_jacobian: Sequence[float], first_element_id: int = 1) -> Dict[int, Colour]:
    """element_colours(): {element id: colour}, as ViewProviderFemMesh.ElementColor takes
    it; quad j (0-based) is element j + first_element_id (meshing.to_femmesh)."""
    return {j + first_element_id: quality_colour(float(v)) for j, v in enumerate(scaled_jacobian)}
