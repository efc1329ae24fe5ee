from typing import Callable, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

__all__ = ["Cancelled", "FacesRefused", "Mesh", "REFUSAL_CODES", "SweptMesh", "mesh_boundary",
           "mesh_option_schema", "mesh_shape", "sweep_shape"]

class Cancelled(RuntimeError): ...
class FacesRefused(ValueError):
    refused_faces: List[dict]

REFUSAL_CODES: Dict[str, str]

class Mesh:
    nodes: np.ndarray
    quads: np.ndarray
    faces: List[dict]
    refused_faces: List[dict]
    quality: dict
    edge_size: Optional[float]
    shape_diagonal: Optional[float]
    changed_edges: List[dict]
    unsewn_edge_pairs: List[Tuple[int, int]]
    sewn_edges: int
    turned_faces: List[int]
    orientation_conflicts: List[Tuple[int, int]]
    contracted_edges: List[int]
    absorbed_faces: List[dict]
    bad_quad_faces: List[dict]
    collapsed_quad_faces: List[dict]
    read_warnings: List[str]
    scaled_jacobian: np.ndarray
    lee_lo: np.ndarray
    mid_nodes: Optional[np.ndarray]
    def __init__(self, data: dict) -> None: ...
    @property
    def template_trees(self) -> List[str]: ...
    @property
    def template_tree(self) -> str: ...
    def face_quads(self, face: int) -> np.ndarray: ...

def mesh_boundary(points: Union[np.ndarray, Sequence[Sequence[float]]], corners: Sequence[int], *,
                  t4_ratio: int = ..., t5_cut_edges: int = ..., max_quads: int = ...,
                  smooth: bool = ..., best_corners: bool = ...) -> Mesh: ...

def mesh_option_schema() -> List[dict]: ...

# Generated from the options schema by scripts/generate_stubs.py.
def mesh_shape(brep_text_or_path: str, *, size: float = ..., faces: Optional[Iterable[int]] = ...,
               corners: Optional[Mapping[int, Sequence[int]]] = ..., keep_going: bool = ...,
               allow_inverted: bool = ..., threads: int = ..., t4_ratio: int = ...,
               t5_cut_edges: int = ..., max_quads: int = ..., smooth: bool = ...,
               progress: Optional[Callable[[str, int, int], Optional[bool]]] = ...,
               read_timeout: Optional[float] = ..., best_corners: bool = ..., min_size: float = ...,
               order: int = ..., sew: bool = ..., sizes: Optional[Dict[str, float]] = ...,
               curvature_segments: int = ..., growth_rate: float = ...) -> Mesh: ...

class SweptMesh:
    nodes: np.ndarray
    hexes: np.ndarray
    scaled_jacobian: np.ndarray
    jacobian_ratio: Optional[np.ndarray]
    solids: List[dict]
    refused_solids: List[dict]
    unshared_faces: List[int]
    face_nodes: Dict[int, np.ndarray]
    edge_size: float
    read_warnings: List[str]
    def __init__(self, data: dict) -> None: ...

def sweep_shape(brep_text_or_path: str, *, size: float = ..., min_size: float = ..., layers: int = ...,
                source: Optional[int] = ..., target: Optional[int] = ..., keep_going: bool = ...,
                smooth: bool = ..., threads: int = ..., read_timeout: Optional[float] = ...,
                order: int = ...) -> SweptMesh: ...
