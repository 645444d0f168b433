"""Type stubs of the extension module `screwbender._screwbender` (the Rust core, PyO3)."""

import os
from typing import Any, Literal, Optional, Sequence, Tuple, TypedDict, Union

import numpy as np
import numpy.typing as npt
from typing_extensions import deprecated

#: Pose input: one pose ``(7,)`` (``x y z qw qx qy qz``) or ``(4, 4)``, or a batch ``(n, 7)`` /
#: ``(n, 4, 4)``; any array-like of real numbers (floats or integers).
PoseArray = npt.ArrayLike
#: Parameters: a number or an array of numbers of any shape.
Parameters = Union[float, npt.ArrayLike]
FloatArray = npt.NDArray[np.float64]
SchemeName = Literal["bspline", "fourpoint", "jarek", "j"]
#: A rule set as ``Motion.rules`` reports it (the id of files, the JS API and the CLI).
RulesId = Literal["direct", "split"]
#: A rule set as accepted: the ids, and the core's former id ``"split-then-tweak"`` (the core's
#: other aliases, such as ``"v1"`` and ``"v2"``, are accepted too).
RulesName = Literal["direct", "split", "split-then-tweak"]
#: A method of the comparison (``compare_methods``).
MethodName = Literal[
    "polyscrew", "bspline", "fourpoint", "jarek", "slerp", "decoupled", "kks", "se3bspline",
    "se3interp", "splitinterp", "rb", "cc0", "cc1", "barr",
]
PathLike = Union[str, "os.PathLike[str]"]

__version__: str
#: The most poses a subdivision may produce (the memory guard), 2**20.
MAX_REFINED_POSES: int

class Kinematics(TypedDict):
    position: FloatArray
    velocity: FloatArray
    acceleration: FloatArray
    angular_velocity: FloatArray
    angular_acceleration: FloatArray

class MetricsTable(TypedDict):
    """The comparison table (``compare_methods``), as ``screwbender compare --json`` prints it
    and the JS API's ``Motion.compareMethods`` returns it."""

    pose_count: int
    closed: bool
    #: The body points (local coordinates) whose trajectories are measured.
    body_points: list[list[float]]
    #: One dict per method, in table order: ``method`` (its name) and the core's metrics, under
    #: the names of the CLI's JSON (a metric that could not be computed is absent or ``None``,
    #: with the reason in ``notes``).
    rows: list[dict[str, Any]]
    #: The methods left out because they do not support these poses, with the reason
    #: (``"cc1: …"``); only when ``methods`` is not given.
    skipped: list[str]

class Motion:
    """Control poses (a cycle or an open sequence) smoothed by screw subdivision.

    ``poses``: ``(n, 7)`` rows ``x y z qw qx qy qz`` (unit quaternions, scalar first; within 1e-3
    of unit norm they are normalised) or ``(n, 4, 4)`` homogeneous matrices (orthonormal within
    1e-4, right-handed), ``n >= 2``. ``closed``: a cycle (the last pose joined back to the first)
    or an open sequence. ``scheme``: ``"bspline"``, ``"fourpoint"`` (default) or ``"jarek"``;
    or ``s=``, the J_s family's parameter (``0`` 4-point, ``0.5`` Jarek, ``1`` B-spline,
    ``|s| <= 4``, direct rules only). ``levels``: subdivision steps (default 5; ``0`` is the plain
    polyscrew). ``rules``: ``"direct"`` (the revised paper's) or ``"split"`` (the first
    version's split-then-tweak rules; ``"split-then-tweak"`` is accepted too). ``times``: when
    each key is reached, in seconds (``n`` for an open motion, ``n + 1`` for a cycle);
    ``velocities``: the rate at each key in poses per second, ``None`` where free (both used by
    ``export``).

    Parameters ``u`` are in coarse units: control pose ``i`` sits at ``u = i``; refined pose
    ``j`` at ``u = j / 2**levels``. Every setter validates the whole new state and raises
    ``ValueError`` / ``TypeError`` naming the element; a refused change leaves the motion as it
    was. The math runs without the GIL.
    """

    def __init__(
        self,
        poses: PoseArray,
        closed: bool = True,
        scheme: Optional[SchemeName] = None,
        levels: Optional[int] = None,
        rules: RulesName = "direct",
        s: Optional[float] = None,
        times: Optional[npt.ArrayLike] = None,
        velocities: Optional[Sequence[Optional[float]]] = None,
        name: Optional[str] = None,
    ) -> None: ...
    @classmethod
    def from_preset(
        cls,
        name: str,
        *,
        closed: Optional[bool] = None,
        scheme: Optional[SchemeName] = None,
        levels: Optional[int] = None,
        rules: RulesName = "direct",
        s: Optional[float] = None,
        times: Optional[npt.ArrayLike] = None,
        velocities: Optional[Sequence[Optional[float]]] = None,
    ) -> "Motion":
        """The preset ``name`` (see ``presets()``), with the preset's scheme and levels unless given."""
    @classmethod
    def from_json(cls, text: str) -> "Motion":
        """A motion document in the CLI's JSON format."""
    @classmethod
    def load(
        cls,
        path: PathLike,
        *,
        node: Optional[str] = None,
        nodes: Optional[Sequence[str]] = None,
        closed: Optional[bool] = None,
    ) -> "Motion":
        """Control poses from a ``.json``, ``.csv``, ``.glb`` or ``.gltf`` file (as ``screwbender import``)."""
    def to_json(self) -> str:
        """The motion document as JSON text."""
    def export(
        self,
        path: PathLike,
        *,
        format: Optional[Literal["glb", "gltf", "csv", "json"]] = None,
        tolerance: Optional[float] = None,
        fps: Optional[float] = None,
        point: Optional[npt.ArrayLike] = None,
        radius: Optional[float] = None,
        control_nodes: bool = False,
    ) -> int:
        """Writes the motion (format from the extension unless given; as ``screwbender export``);
        returns the number of samples written."""
    def copy(self) -> "Motion": ...
    def __copy__(self) -> "Motion": ...
    def __deepcopy__(self, memo: object) -> "Motion": ...
    def __len__(self) -> int:
        """The number of control poses (also ``pose_count``)."""
    @property
    def pose_count(self) -> int:
        """The number of control poses (JS ``poseCount``)."""
    poses: FloatArray
    """The control poses, ``(n, 7)``; assign ``(n, 7)`` or ``(n, 4, 4)``."""
    def pose(self, i: int) -> FloatArray:
        """Control pose ``i``, ``(7,)``."""
    def set_pose(self, i: int, pose: PoseArray) -> None:
        """Replaces control pose ``i`` (``(7,)`` or ``(4, 4)``)."""
    def insert_pose(self, i: int, pose: Optional[PoseArray] = None) -> int:
        """Inserts a pose between control poses ``i`` and ``i + 1`` and returns its index.

        Without ``pose``, the screw midpoint ``screw(P_i, 0.5, P_{i+1})`` (a cycle's last pose is
        followed by its first; after an open motion's last pose a pose must be given).
        Raises ``ValueError`` naming the element, and changes nothing, on bad input."""
    def remove_pose(self, i: int) -> None:
        """Removes control pose ``i`` (a motion keeps at least 2 poses)."""
    closed: bool
    name: Optional[str]
    times: Optional[list[float]]
    velocities: Optional[list[Optional[float]]]
    scheme: SchemeName
    """``"bspline"``, ``"fourpoint"``, ``"jarek"``, or ``"j"`` for the J_s family."""
    s: float
    """The J_s parameter of the scheme (``1`` B-spline, ``0`` 4-point, ``0.5`` Jarek); setting it selects the J_s family."""
    @property
    def rules(self) -> RulesId:
        """The rule set: ``"direct"`` or ``"split"`` (the id of files, the JS API and the CLI);
        setting it also accepts ``"split-then-tweak"``."""
    @rules.setter
    def rules(self, value: RulesName) -> None: ...
    levels: int
    def warnings(self) -> list[str]:
        """Warnings about the options on these poses (e.g. a span close to a half turn)."""
    @property
    def refined_count(self) -> int:
        """How many poses ``subdivide()`` returns."""
    @property
    def domain(self) -> Tuple[float, float]:
        """``(0, n)`` for a cycle of ``n`` poses, ``(0, m - 1)`` for an open sequence."""
    def subdivide(self) -> FloatArray:
        """The refined poses, ``(N, 7)``."""
    def refined_matrices(self) -> FloatArray:
        """The refined poses as homogeneous matrices, ``(N, 4, 4)`` (JS ``refinedMatrices``)."""
    @deprecated("Motion.matrices() is deprecated: use Motion.refined_matrices()")
    def matrices(self) -> FloatArray:
        """Former name of :meth:`refined_matrices`, kept for one release: it warns
        (``DeprecationWarning``)."""
    def poses_at(self, u: Parameters) -> FloatArray:
        """The poses at ``u``: ``(7,)`` for a number, ``u.shape + (7,)`` for an array."""
    def sample(self, count: int) -> FloatArray:
        """``count`` poses at uniformly spaced parameters, ``(count, 7)``."""
    def kinematics_at(self, u: Parameters, point: Optional[npt.ArrayLike] = None) -> Kinematics:
        """Closed-form kinematics at ``u`` of the body point ``point`` (local coordinates,
        default the origin), world frame, per unit of ``u``: arrays of shape ``u.shape + (3,)``
        (JS ``kinematicsAt``)."""
    @deprecated("Motion.kinematics() is deprecated: use Motion.kinematics_at()")
    def kinematics(self, u: Parameters, point: Optional[npt.ArrayLike] = None) -> Kinematics:
        """Former name of :meth:`kinematics_at`, kept for one release: it warns
        (``DeprecationWarning``)."""
    def compare_methods(
        self,
        methods: Union[None, str, Sequence[MethodName]] = None,
        body_points: Optional[npt.ArrayLike] = None,
    ) -> MetricsTable:
        """The metrics of the comparison methods on the control poses (``closed`` as this
        motion; its scheme, rules and levels play no part), as ``screwbender compare --json``
        prints them and JS ``Motion.compareMethods`` returns them: ``compare_methods(m.poses,
        m.closed, methods, body_points)``."""

def screw(a: PoseArray, t: Parameters, b: PoseArray) -> FloatArray:
    """``screw(a, t, b)``: the pose after the fraction ``t`` of the screw motion from ``a`` to ``b``
    (``t = 0`` is ``a``, ``t = 1`` is ``b``, any real ``t`` extrapolates); equal to
    ``a · exp(t · log(a⁻¹ b))`` (``modern_robotics.ScrewTrajectory``'s motion) and to dual
    quaternion ScLERP.

    ``a``, ``b``: one pose each (``(7,)`` or ``(4, 4)``) with ``t`` a number -> ``(7,)`` or an array
    -> ``t.shape + (7,)`` (the logarithm computed once); or batches ``(n, 7)`` / ``(n, 4, 4)`` (one
    side may be a single pose) with ``t`` a number or ``(n,)`` -> ``(n, 7)``, computed several at a
    time on SIMD lanes, bit for bit the same as one at a time.
    """

def compare_methods(
    poses: PoseArray,
    closed: bool = True,
    methods: Union[None, str, Sequence[MethodName]] = None,
    body_points: Optional[npt.ArrayLike] = None,
) -> MetricsTable:
    """The metrics of the comparison methods on the control poses ``poses`` (pose ``i`` at
    ``u = i``; ``closed``: a cycle), the table ``screwbender compare --json`` prints (the same
    field names, parsed with ``json.loads``) and JS ``Motion.compareMethods`` returns.

    ``methods``: ``None`` (every method that applies; one that does not support these poses is
    listed in ``skipped``), a list of names (``"polyscrew"``, ``"bspline"``, ``"fourpoint"``,
    ``"jarek"``, ``"slerp"``, ``"decoupled"``, ``"kks"``, ``"se3bspline"``, ``"se3interp"``,
    ``"splitinterp"``, ``"rb"``, ``"cc0"``, ``"cc1"``, ``"barr"``; ``"se3interp"``,
    ``"splitinterp"`` and ``"barr"`` only when named; case-insensitive, a name given twice is measured once) or one string of names
    separated by commas (as the CLI's ``--methods``). ``body_points``: the local points whose
    trajectories are measured, ``(k, 3)`` with ``k`` from 1 to 16 (default ``(0, 0, 0)`` and
    ``(2, 0, 0)``). The CLI's extra ``objectives`` (when ``barr`` is named) are not computed.

    An unknown name raises ``ValueError`` naming it (``methods[1]: unknown value 'x' (expected
    polyscrew, …)``); a named method that rejects the poses (``cc1`` on a cycle) raises
    ``ValueError`` prefixed with its name. Computed without the GIL; it takes a while (every
    metric is measured at several steps).
    """

def method_poses(
    method: MethodName,
    poses: PoseArray,
    u: Parameters,
    closed: bool = True,
) -> FloatArray:
    """The poses of one comparison method's motion through the control poses ``poses`` (pose
    ``i`` at ``u = i``; ``closed``: a cycle of period ``n``, else an open sequence over
    ``[0, n - 1]``) at the parameters ``u`` (a number -> ``(7,)``, an array -> ``u.shape +
    (7,)``), rows ``x y z qw qx qy qz``. The motion each row of ``compare_methods`` measures, for
    checks against other implementations. An unknown name or a method that rejects the poses
    raises ``ValueError`` naming it. Computed without the GIL.
    """

class FitReport(TypedDict):
    """The residuals of :func:`fit` (as ``screwbender fit --json``): distances in scene units,
    angles in radians, over all samples."""

    method: str
    controls: int
    samples: int
    rms_position: float
    max_position: float
    rms_angle: float
    max_angle: float
    rms_deviation: float
    max_deviation: float
    iterations: int

def fit(
    path: Union[str, "os.PathLike[str]"],
    *,
    method: Literal["screwbender", "se3bspline"] = "screwbender",
    controls: Optional[int] = None,
    tolerance: Optional[float] = None,
    smoothness: float = 0.0,
    robust: Literal["none", "huber", "cauchy"] = "none",
    robust_scale: Optional[float] = None,
    radius: float = 1.0,
    node: Optional[str] = None,
    nodes: Optional[Sequence[str]] = None,
) -> Tuple[Motion, FitReport]:
    """The open motion ``method`` (``"screwbender"``: the cubic B-spline scheme;
    ``"se3bspline"``: the cumulative B-spline on SE(3)) fitted to the timestamped poses of the
    file at ``path`` (read as :meth:`Motion.load` reads it), with exactly one of ``controls`` (a
    count) and ``tolerance`` (the RMS deviation, distance + ``radius`` × angle, to stay within);
    ``smoothness`` weighs the smoothness term, ``robust`` a loss against outliers. Returns the
    motion (the fitted control poses with their key times, B-spline scheme) and the residual
    report. Raises ``ValueError`` naming the bad element. Computed without the GIL.
    """

def measure_fit(
    motion: Motion,
    path: Union[str, "os.PathLike[str]"],
    *,
    method: Literal["screwbender", "se3bspline"] = "screwbender",
    radius: float = 1.0,
    node: Optional[str] = None,
    nodes: Optional[Sequence[str]] = None,
) -> FitReport:
    """The residuals of the open motion ``method`` whose control poses (and key times) are
    ``motion``'s against the timestamped poses of the file at ``path`` (read as :func:`fit`
    reads it): the report :func:`fit` gives for its own result, for any motion (a reduced or
    edited one; ``iterations`` 0). Control poses without key times are spread over the samples'
    time span, as a fit places them. Raises ``ValueError`` naming the bad element. Computed
    without the GIL.
    """

def presets() -> list[str]:
    """The preset ids for ``Motion.from_preset``."""

def preset_descriptions() -> list[Tuple[str, str, str]]:
    """``(id, label, description)`` of every preset."""

def preset_display(id: str) -> dict[str, Any]:
    """How the page shows preset ``id``: ``name`` (in words), ``strobe`` (copies of the object),
    ``selected`` (the pose selected on load, or ``None``) and ``body_points`` (the local points
    whose trajectories are drawn, a list of ``[x, y, z]``). An unknown id raises ``ValueError``
    naming ``id``.
    """
