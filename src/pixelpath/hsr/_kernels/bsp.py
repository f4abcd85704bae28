"""Compiled kernels of the BSP-tree method: build once in object space, traverse per eye.

The tree lives in flat arrays. Node k has a splitting plane ``plane[k]`` (unit normal and
offset: normal · x + offset = 0), its back and front children ``children[k]`` (-1 for none),
and the polygons lying in its plane, ``items[first[k] : first[k] + count[k]]`` (fragment
indices). Infinite planes of the scene (``infinite[k]`` >= 0) are the splitting planes of the
top levels: they are perfect splitters (nothing of them lies off their plane), and their
per-camera grid triangles are attached to their nodes at render time (:func:`route_planes`).

Build (:func:`build`): a stack of tasks, each a node and a run of fragment indices in a work
array. A task partitions its run by the node's plane into the polygons in the plane (kept at
the node), behind it and in front of it; a triangle that straddles the plane is cut in two or
three (:func:`pixelpath.raster._setup_kernels.cut_triangle`) and its pieces go to their sides. The
splitter of a finite node is the best of a few candidates, scored on a sample of the run by
``|front - back| + SPLIT_WEIGHT · splits``: the planes of a few of the run's polygons, and for
long runs three axis-aligned planes through the middle of the run (a node with such a *free*
plane often holds no polygon; without them a convex mesh, whose every face has all the others
behind it, would make a chain as deep as it has faces).
"""

from __future__ import annotations

import numpy as np

from pixelpath._jit import njit
from pixelpath.raster._setup_kernels import _grown, _grown_rows, cut_triangle

CANDIDATES = 8  # polygon planes scored per node
SAMPLE = 128  # polygons of a run the candidates are scored on
SPLIT_WEIGHT = 24  # a split costs as much as this much imbalance
FREE_PLANES_FROM = 64  # runs at least this long also try axis-aligned planes

# Slots of the statistics array.
NODES = 0
DEPTH = 1
SPLITS = 2
FREE = 3  # nodes with an axis-aligned (free) splitting plane
STATS = 4


@njit(inline="always")
def _distance(vertices, v, plane):
    return (
        plane[0] * vertices[v, 0] + plane[1] * vertices[v, 1] + plane[2] * vertices[v, 2]
        + plane[3]
    )


@njit(inline="always")
def _classify(vertices, corners, plane, eps):
    """-1 behind, +1 in front, 0 in the plane, 2 straddling (within eps counts as on it)."""
    d0 = _distance(vertices, corners[0], plane)
    d1 = _distance(vertices, corners[1], plane)
    d2 = _distance(vertices, corners[2], plane)
    low = min(d0, d1, d2)
    high = max(d0, d1, d2)
    if high <= eps and low >= -eps:
        return 0
    if low >= -eps:
        return 1
    if high <= eps:
        return -1
    return 2


@njit(from_python=False)
def _new_node(planes, children, first, count, infinite, parent, side, nodes, owner, branch):
    """Append a node (no plane yet) under ``owner`` on side ``branch``; return the arrays."""
    if nodes == planes.shape[0]:
        planes = _grown_rows(planes, nodes + 1)
        children = _grown_rows(children, nodes + 1)
        first = _grown(first, nodes + 1)
        count = _grown(count, nodes + 1)
        infinite = _grown(infinite, nodes + 1)
        parent = _grown(parent, nodes + 1)
        side = _grown(side, nodes + 1)
    children[nodes, 0] = -1
    children[nodes, 1] = -1
    first[nodes] = 0
    count[nodes] = 0
    infinite[nodes] = -1
    parent[nodes] = owner
    side[nodes] = branch
    if owner >= 0:
        children[owner, 0 if branch < 0 else 1] = nodes
    return planes, children, first, count, infinite, parent, side


@njit(from_python=False)
def _infinite_applies(k, node, branch, infinite, parent, side, relation):
    """Whether infinite plane k passes through the cell of side ``branch`` of ``node``.

    It does unless it is parallel to the plane of an infinite ancestor and lies on the other
    side of it (``relation[k, j]`` is 0 for planes that cross, else the side k lies on).
    """
    while node >= 0:
        j = infinite[node]
        if j >= 0 and relation[k, j] != 0 and relation[k, j] != branch:
            return False
        branch = side[node]
        node = parent[node]
    return True


@njit(from_python=False)
def _next_infinite(level, node, branch, infinite, parent, side, relation):
    """Return the first infinite plane from ``level`` on in that cell, or the plane count."""
    for k in range(level, relation.shape[0]):
        if _infinite_applies(k, node, branch, infinite, parent, side, relation):
            return k
    return relation.shape[0]


@njit(from_python=False)
def _score(vertices, fragments, work, start, stop, step, plane, eps):
    """|front - back| + SPLIT_WEIGHT · splits over every ``step``-th polygon of the run."""
    front = 0
    back = 0
    splits = 0
    for i in range(start, stop, step):
        where = _classify(vertices, fragments[work[i]], plane, eps)
        if where == 1:
            front += 1
        elif where == -1:
            back += 1
        elif where == 2:
            splits += 1
    return abs(front - back) + SPLIT_WEIGHT * splits, front, back


@njit(from_python=False)
def _choose_splitter(vertices, fragments, source, planes, work, start, stop, eps, best, scratch):
    """Write the best splitting plane for the run into ``best``; return whose plane it is.

    Returns the input triangle (``source``) whose plane was chosen, or -1 for a free
    (axis-aligned) plane. ``scratch`` is (3, 4) work space: the run's bounding box and a
    candidate plane.
    """
    m = stop - start
    step = max(1, m // SAMPLE)
    tried = min(CANDIDATES, m)
    best_score = -1
    chosen = -1
    for c in range(tried):
        owner = source[work[start + (c * m) // tried]]
        plane = planes[owner]
        score, _, _ = _score(vertices, fragments, work, start, stop, step, plane, eps)
        if best_score < 0 or score < best_score:
            best_score = score
            chosen = owner
            for k in range(4):
                best[k] = plane[k]
    if m < FREE_PLANES_FROM:
        return chosen
    low, high, candidate = scratch[0], scratch[1], scratch[2]
    for axis in range(3):
        low[axis] = np.inf
        high[axis] = -np.inf
    for i in range(start, stop, step):
        for corner in range(3):
            v = fragments[work[i], corner]
            for axis in range(3):
                low[axis] = min(low[axis], vertices[v, axis])
                high[axis] = max(high[axis], vertices[v, axis])
    for axis in range(3):
        for k in range(3):
            candidate[k] = 1.0 if k == axis else 0.0
        candidate[3] = -0.5 * (low[axis] + high[axis])
        score, front, back = _score(vertices, fragments, work, start, stop, step, candidate, eps)
        if front > 0 and back > 0 and score < best_score:
            best_score = score
            chosen = -1
            for k in range(4):
                best[k] = candidate[k]
    return chosen


@njit(inline="always")
def _push(array, n, value):
    """Append ``value`` at ``array[n]`` (growing the array); return the array and n + 1."""
    if n == array.shape[0]:
        array = _grown(array, n + 1)
    array[n] = value
    return array, n + 1


@njit(from_python=False)
def _barycentric(v, t, triangles, base, weights, out):
    """Weights of vertex v over the corners of original triangle t (v is a corner or a cut)."""
    if v >= base:
        for k in range(3):
            out[k] = weights[v - base, k]
        return
    for k in range(3):
        out[k] = 1.0 if triangles[t, k] == v else 0.0


@njit(from_python=False)
def _record_cuts(before, count, base, t, triangles, cut_edges, cut_params, blend_corners,
                 blend_weights):
    """Store, for the vertices just cut from a piece of triangle t, their blend of t's corners.

    Returns the (possibly grown) blend arrays.
    """
    if count - base > blend_corners.shape[0]:
        blend_corners = _grown_rows(blend_corners, count - base)
        blend_weights = _grown_rows(blend_weights, count - base)
    wi = np.empty(3)
    wj = np.empty(3)
    for row in range(before, count):
        slot = row - before
        s = cut_params[slot]
        _barycentric(cut_edges[slot, 0], t, triangles, base, blend_weights, wi)
        _barycentric(cut_edges[slot, 1], t, triangles, base, blend_weights, wj)
        for k in range(3):
            blend_corners[row - base, k] = triangles[t, k]
            blend_weights[row - base, k] = wi[k] + s * (wj[k] - wi[k])
    return blend_corners, blend_weights


@njit
def build(vertices, triangles, planes, infinite_planes, relation, eps, stats):
    """Build the BSP tree of the triangles below the infinite planes.

    Parameters
    ----------
    vertices : (V, k) float64
        Vertex rows: world position first (3 columns), then attributes (normals) that cut
        vertices interpolate.
    triangles : (T, 3) intp
        The scene's finite triangles (non-zero area).
    planes : (T, 4) float64
        Their planes: unit normal and offset.
    infinite_planes : (P, 4) float64
        The scene's infinite planes, in scene order.
    relation : (P, P) int8
        ``relation[k, j]``: 0 when planes k and j cross, else the side of j plane k lies on.
    eps : float
        Distance within which a point lies on a plane.
    stats : (STATS,) int64, out
        Nodes, depth, splits, nodes with a free plane.

    Returns
    -------
    vertices, count
        The vertex rows with the cut vertices appended, and how many are in use.
    blend_corners, blend_weights : (count - V, 3)
        Each cut vertex as a blend of the corners of the triangle it was cut from.
    fragments : (F, 3) intp; source : (F,) intp
        The pieces the tree holds and the triangle each comes from.
    node_planes (N, 4), children (N, 2), first (N,), count (N,), items (I,), infinite (N,)
        The tree (``infinite[k]``: the infinite plane of node k, -1 for a finite node).
    """
    base = vertices.shape[0]
    n_vertices = base
    n = triangles.shape[0]
    fragments = np.empty((n + n // 2 + 16, 3), dtype=np.intp)
    source = np.empty(fragments.shape[0], dtype=np.intp)
    for t in range(n):
        for k in range(3):
            fragments[t, k] = triangles[t, k]
        source[t] = t
    n_fragments = n
    blend_corners = np.empty((16, 3), dtype=np.intp)
    blend_weights = np.empty((16, 3))
    size = 2 * n + 16
    node_planes = np.empty((size, 4))
    children = np.empty((size, 2), dtype=np.intp)
    first = np.empty(size, dtype=np.intp)
    count = np.empty(size, dtype=np.intp)
    infinite = np.empty(size, dtype=np.intp)
    parent = np.empty(size, dtype=np.intp)
    side = np.empty(size, dtype=np.intp)
    items = np.empty(n + 16, dtype=np.intp)
    n_items = 0
    # The runs of the pending tasks lie in ``work`` in stack order, the top task's run last;
    # a task's children runs overwrite its own, so ``work`` holds only live polygons.
    work = np.empty(n + n // 2 + 16, dtype=np.intp)
    for t in range(n):
        work[t] = t
    run = np.empty(n + 16, dtype=np.intp)  # the run being partitioned
    ahead = np.empty(n + 16, dtype=np.intp)  # its front part while the back part is written
    tasks = np.empty((64, 4), dtype=np.intp)  # node, start, stop, level
    depths = np.empty(64, dtype=np.intp)
    n_tasks = 0
    nodes = 0
    n_planes = relation.shape[0]
    if n > 0 or n_planes > 0:
        root, no_parent = nodes, nodes - 1
        node_planes, children, first, count, infinite, parent, side = _new_node(
            node_planes, children, first, count, infinite, parent, side, root, no_parent, root
        )
        nodes = 1
        tasks[0, 0], tasks[0, 1], tasks[0, 2], tasks[0, 3] = 0, 0, n, 0
        depths[0] = 1
        n_tasks = 1
    plane = np.empty(4)
    scratch = np.empty((3, 4))
    pieces = np.empty((3, 4), dtype=np.intp)
    cut_edges = np.empty((2, 2), dtype=np.intp)
    cut_params = np.empty(2)
    distances = np.empty(3)
    while n_tasks > 0:
        n_tasks -= 1
        node, start, stop = tasks[n_tasks, 0], tasks[n_tasks, 1], tasks[n_tasks, 2]
        level = tasks[n_tasks, 3]
        depth = depths[n_tasks]
        stats[DEPTH] = max(stats[DEPTH], depth)
        j = _next_infinite(level, parent[node], side[node], infinite, parent, side, relation)
        owner = -1  # the input triangle whose plane splits here, if any
        if j < n_planes:
            for k in range(4):
                plane[k] = infinite_planes[j, k]
            infinite[node] = j
            level = j + 1
        else:
            owner = _choose_splitter(
                vertices, fragments, source, planes, work, start, stop, eps, plane, scratch
            )
            stats[FREE] += int(owner < 0)
            level = n_planes
        for k in range(4):
            node_planes[node, k] = plane[k]
        # Partition the run: in the plane (kept here), behind (written in place), in front.
        m = stop - start
        if m > run.shape[0]:
            run = np.empty(m + m // 2, dtype=np.intp)
        for i in range(m):
            run[i] = work[start + i]
        n_work = start
        n_ahead = 0
        first[node] = n_items
        for i in range(m):
            f = run[i]
            # The splitter's own triangle (and its pieces) stays here even where rounding puts
            # a corner off its plane: a node split by a polygon's plane then always takes that
            # polygon from its run, so the build ends.
            where = 0 if source[f] == owner else _classify(vertices, fragments[f], plane, eps)
            if where == 0:
                items, n_items = _push(items, n_items, f)
            elif where < 0:
                work, n_work = _push(work, n_work, f)
            elif where == 1:
                ahead, n_ahead = _push(ahead, n_ahead, f)
            else:
                for k in range(3):
                    distances[k] = _distance(vertices, fragments[f, k], plane)
                before = n_vertices
                vertices, n_vertices, made = cut_triangle(
                    vertices, n_vertices, fragments[f], distances, eps, pieces, cut_edges,
                    cut_params,
                )
                blend_corners, blend_weights = _record_cuts(
                    before, n_vertices, base, source[f], triangles, cut_edges, cut_params,
                    blend_corners, blend_weights,
                )
                stats[SPLITS] += 1
                if n_fragments + made > fragments.shape[0]:
                    fragments = _grown_rows(fragments, n_fragments + made)
                    source = _grown(source, n_fragments + made)
                for piece in range(made):
                    g = n_fragments
                    n_fragments += 1
                    for k in range(3):
                        fragments[g, k] = pieces[piece, k]
                    source[g] = source[f]
                    if pieces[piece, 3] < 0:
                        work, n_work = _push(work, n_work, g)
                    else:
                        ahead, n_ahead = _push(ahead, n_ahead, g)
        count[node] = n_items - first[node]
        back_stop = n_work
        for i in range(n_ahead):
            work, n_work = _push(work, n_work, ahead[i])
        # Children: a run of polygons, or a cell an infinite plane still has to divide. The
        # back child is pushed first, so the front one (whose run is last) is taken next.
        for branch in (-1, 1):
            run_start, run_stop = (start, back_stop) if branch < 0 else (back_stop, n_work)
            more = _next_infinite(level, node, branch, infinite, parent, side, relation)
            if run_stop == run_start and more == n_planes:
                continue
            node_planes, children, first, count, infinite, parent, side = _new_node(
                node_planes, children, first, count, infinite, parent, side, nodes, node,
                branch,
            )
            if n_tasks == tasks.shape[0]:
                tasks = _grown_rows(tasks, n_tasks + 1)
                depths = _grown(depths, n_tasks + 1)
            tasks[n_tasks, 0], tasks[n_tasks, 1], tasks[n_tasks, 2] = nodes, run_start, run_stop
            tasks[n_tasks, 3] = level
            depths[n_tasks] = depth + 1
            n_tasks += 1
            nodes += 1
    stats[NODES] = nodes
    cuts = n_vertices - base
    return (
        vertices, n_vertices, blend_corners[:cuts], blend_weights[:cuts],
        fragments[:n_fragments], source[:n_fragments], node_planes[:nodes], children[:nodes],
        first[:nodes], count[:nodes], items[:n_items], infinite[:nodes],
    )


@njit
def route_planes(node_planes, children, infinite, vertices, triangles, plane_index, eps):
    """Attach the per-camera grid triangles of the infinite planes to their nodes.

    Plane k's node appears in every cell of the infinite planes above it that plane k passes
    through; a grid triangle goes down the infinite nodes above plane k's, cut by their
    planes where it crosses them, and each piece lands on the node of plane k in its cell.

    Parameters
    ----------
    vertices : (V, k) float64
        Rows of the grid vertices (world position first); cut vertices are appended.
    triangles : (G, 3) intp
        Grid triangles; ``plane_index[g]`` is the infinite plane triangle g lies in.

    Returns
    -------
    vertices, count, blend_corners, blend_weights
        As for :func:`build` (cut vertices as blends of their grid triangle's corners).
    pieces : (M, 3) intp; piece_node : (M,) intp; piece_source : (M,) intp
        The triangles to draw, the node each is drawn at, the grid triangle it comes from.
    """
    base = vertices.shape[0]
    n_vertices = base
    blend_corners = np.empty((16, 3), dtype=np.intp)
    blend_weights = np.empty((16, 3))
    size = triangles.shape[0] + 16
    pieces = np.empty((size, 3), dtype=np.intp)
    piece_node = np.empty(size, dtype=np.intp)
    piece_source = np.empty(size, dtype=np.intp)
    n_pieces = 0
    pending = np.empty((16, 4), dtype=np.intp)  # node, three corners
    corners = np.empty(3, dtype=np.intp)
    cut = np.empty((3, 4), dtype=np.intp)
    cut_edges = np.empty((2, 2), dtype=np.intp)
    cut_params = np.empty(2)
    distances = np.empty(3)
    for g in range(triangles.shape[0]):
        pending[0, 0] = 0 if node_planes.shape[0] > 0 else -1
        for k in range(3):
            pending[0, k + 1] = triangles[g, k]
        n_pending = 1
        while n_pending > 0:
            n_pending -= 1
            node = pending[n_pending, 0]
            if node < 0 or infinite[node] < 0:
                continue  # no node of this plane in the cell (cannot happen for valid trees)
            if infinite[node] == plane_index[g]:
                if n_pieces == pieces.shape[0]:
                    pieces = _grown_rows(pieces, n_pieces + 1)
                    piece_node = _grown(piece_node, n_pieces + 1)
                    piece_source = _grown(piece_source, n_pieces + 1)
                for k in range(3):
                    pieces[n_pieces, k] = pending[n_pending, k + 1]
                piece_node[n_pieces] = node
                piece_source[n_pieces] = g
                n_pieces += 1
                continue
            plane = node_planes[node]
            for k in range(3):
                corners[k] = pending[n_pending, k + 1]
            where = _classify(vertices, corners, plane, eps)
            if where != 2:  # a piece in the plane (coincident planes) goes in front, as built
                pending[n_pending, 0] = children[node, 0 if where < 0 else 1]
                n_pending += 1
                continue
            for k in range(3):
                distances[k] = _distance(vertices, corners[k], plane)
            before = n_vertices
            vertices, n_vertices, made = cut_triangle(
                vertices, n_vertices, corners, distances, eps, cut, cut_edges, cut_params
            )
            blend_corners, blend_weights = _record_cuts(
                before, n_vertices, base, g, triangles, cut_edges, cut_params, blend_corners,
                blend_weights,
            )
            if n_pending + made > pending.shape[0]:
                pending = _grown_rows(pending, n_pending + made)
            for piece in range(made):
                pending[n_pending, 0] = children[node, 0 if cut[piece, 3] < 0 else 1]
                for k in range(3):
                    pending[n_pending, k + 1] = cut[piece, k]
                n_pending += 1
    cuts = n_vertices - base
    return (
        vertices, n_vertices, blend_corners[:cuts], blend_weights[:cuts], pieces[:n_pieces],
        piece_node[:n_pieces], piece_source[:n_pieces],
    )


@njit
def traverse(node_planes, children, first, count, items, extra_first, extra_count, extra_items,
             eye, order):
    """Write the tree's polygons into ``order`` back to front as seen from ``eye``.

    ``eye`` (4,) is homogeneous (``Camera.viewpoint``): w = 0 is an orthographic viewer at
    infinity, in front of a plane when the plane's normal points its way.

    At each node the subtree on the far side of its plane comes first, then the node's own
    polygons (``extra_items`` of the node, then its ``items``), then the near subtree; an
    explicit stack replaces the recursion. Returns (polygons written, nodes visited).
    """
    stack = np.empty(64, dtype=np.intp)  # node k to visit, or -(k + 1): draw node k
    top = 0
    if node_planes.shape[0] > 0:
        stack[0] = 0
        top = 1
    drawn = 0
    visited = 0
    while top > 0:
        top -= 1
        entry = stack[top]
        if entry < 0:
            node = -entry - 1
            for k in range(extra_first[node], extra_first[node] + extra_count[node]):
                order[drawn] = extra_items[k]
                drawn += 1
            # Coplanar polygons in decreasing index: ties go to the lower one, as in the
            # z-buffer (the later one painted wins).
            for k in range(first[node] + count[node] - 1, first[node] - 1, -1):
                order[drawn] = items[k]
                drawn += 1
            continue
        visited += 1
        plane = node_planes[entry]
        eye_side = (plane[0] * eye[0] + plane[1] * eye[1] + plane[2] * eye[2]
                    + plane[3] * eye[3])
        near = children[entry, 1] if eye_side > 0.0 else children[entry, 0]
        far = children[entry, 0] if eye_side > 0.0 else children[entry, 1]
        if top + 3 > stack.shape[0]:
            stack = _grown(stack, top + 3)
        if near >= 0:
            stack[top] = near
            top += 1
        stack[top] = -entry - 1
        top += 1
        if far >= 0:
            stack[top] = far
            top += 1
    return drawn, visited


@njit
def draw_order(sequence, source, n_polygons, order):
    """Order drawable triangles as the polygons they come from appear in ``sequence``.

    ``source[t]`` is the polygon of drawable triangle t (several pieces of one polygon after
    frustum clipping keep their relative order); triangles of polygons not in the sequence
    are left out. Writes ``order`` and returns how many it holds. A counting sort: O(T).
    """
    rank = np.full(n_polygons, -1, dtype=np.intp)
    for i in range(sequence.shape[0]):
        rank[sequence[i]] = i
    placed = 0
    starts = np.zeros(sequence.shape[0] + 1, dtype=np.intp)
    for t in range(source.shape[0]):
        if rank[source[t]] >= 0:
            starts[rank[source[t]] + 1] += 1
    for i in range(sequence.shape[0]):
        starts[i + 1] += starts[i]
    for t in range(source.shape[0]):
        r = rank[source[t]]
        if r >= 0:
            order[starts[r]] = t
            starts[r] += 1
            placed += 1
    return placed


def warmup() -> None:
    """Build, route and traverse a tiny tree: two crossing triangles under one plane."""
    vertices = np.array(
        [[-1.0, 0.5, -1.0], [1.0, 0.5, -1.0], [0.0, 1.5, -1.0],
         [-1.0, 0.5, -2.0], [1.0, 1.0, 0.0], [0.0, 1.5, -0.5]]
    )
    rows = np.hstack((vertices, np.zeros((6, 3))))
    triangles = np.array([[0, 1, 2], [3, 4, 5]], dtype=np.intp)
    # The triangles' own planes: a plane its polygon does not lie in would never empty a run.
    normals = np.cross(vertices[[1, 4]] - vertices[[0, 3]], vertices[[2, 5]] - vertices[[0, 3]])
    normals /= np.sqrt((normals * normals).sum(axis=1)).reshape(2, 1)
    planes = np.hstack((normals, -(normals * vertices[[0, 3]]).sum(axis=1).reshape(2, 1)))
    floor = np.array([[0.0, 1.0, 0.0, 0.0]])
    stats = np.zeros(STATS, dtype=np.int64)
    built = build(rows, triangles, planes, floor, np.zeros((1, 1), dtype=np.int8), 1e-9, stats)
    node_planes, children, first, count, items, infinite = built[6:]
    grid = np.array([[-5.0, 0.0, -5.0, 0, 1, 0], [5.0, 0.0, -5.0, 0, 1, 0],
                     [0.0, 0.0, 5.0, 0, 1, 0]])
    routed = route_planes(node_planes, children, infinite, grid,
                          np.array([[0, 1, 2]], dtype=np.intp), np.zeros(1, dtype=np.intp), 1e-9)
    nodes = node_planes.shape[0]
    extra_first = np.zeros(nodes, dtype=np.intp)
    extra_count = np.zeros(nodes, dtype=np.intp)
    extra_count[0] = routed[4].shape[0]
    extra_items = np.arange(extra_count[0]) + built[4].shape[0]
    order = np.empty(items.shape[0] + extra_items.shape[0], dtype=np.intp)
    drawn, _ = traverse(node_planes, children, first, count, items, extra_first, extra_count,
                        extra_items, np.array([0.0, 1.0, 5.0, 1.0]), order)
    draw_order(order[:drawn], np.zeros(1, dtype=np.intp), int(order[:drawn].max(initial=0)) + 1,
               np.empty(1, dtype=np.intp))
