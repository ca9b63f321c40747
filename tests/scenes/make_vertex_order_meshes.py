#!/usr/bin/env python3
"""Writes the test meshes about vertex order, folds and flat cells from the
gmsh meshes meshes/bar_2d.msh and meshes/bar_3d.msh (format 4.1):

  mixed_order_bar_{2d,3d}.msh   the bar with two vertices swapped in every
                                other cell (as DOLFIN/meshio write cells:
                                about half negatively oriented); a valid mesh
  bad_folded_mesh_2d.msh        bar_2d with one interior node pushed through
                                the opposite edge of one of its triangles
  bad_folded_mesh_3d.msh        mixed_order_bar_3d with one interior node
                                pushed through the opposite face of one of
                                its tetrahedra
  bad_flat_cell_mesh_{2d,3d}.msh  the bar with one interior node moved onto
                                the opposite edge (face) of one of its cells:
                                that cell has zero area (volume)

and prints which gmsh elements are inverted or flat. Run from anywhere:
  python3 tests/scenes/make_vertex_order_meshes.py
"""
import os

here = os.path.dirname(os.path.abspath(__file__))
meshes = os.path.join(here, '..', '..', 'meshes')


def read(path, dim):
    """Lines, node tag -> (line index, coordinates), and the cells
    (element tag, line index, node tags) of a gmsh 4.1 file of dimension
    dim."""
    lines = open(path).read().split('\n')
    nodes, cells = {}, []
    i = 0
    while i < len(lines):
        if lines[i] == '$Nodes':
            n_blocks = int(lines[i + 1].split()[0])
            j = i + 2
            for _ in range(n_blocks):
                n = int(lines[j].split()[3])
                tags = [int(lines[j + 1 + k]) for k in range(n)]
                for k, tag in enumerate(tags):
                    line = j + 1 + n + k
                    nodes[tag] = (line, [float(x) for x in lines[line].split()[:3]])
                j += 1 + 2 * n
            i = j
        elif lines[i] == '$Elements':
            n_blocks = int(lines[i + 1].split()[0])
            j = i + 2
            for _ in range(n_blocks):
                entity_dim, _, element_type, n = map(int, lines[j].split())
                for k in range(n):
                    values = [int(x) for x in lines[j + 1 + k].split()]
                    if element_type == (2 if dim == 2 else 4):
                        cells.append((values[0], j + 1 + k, values[1:]))
                j += 1 + n
            i = j
        else:
            i += 1
    return lines, nodes, cells


def det(points):
    if len(points) == 3:
        a, b, c = points
        return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    a, b, c, d = points
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    w = [d[k] - a[k] for k in range(3)]
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def write(lines, name):
    with open(os.path.join(here, name), 'w') as f:
        f.write('\n'.join(lines))


def mixed_order(dim):
    lines, nodes, cells = read(os.path.join(meshes, 'bar_%dd.msh' % dim), dim)
    swapped = 0
    for k, (tag, line, vertices) in enumerate(cells):
        if k % 2 == 1:
            v = list(vertices)
            v[0], v[1] = v[1], v[0]
            lines[line] = ' '.join(str(x) for x in [tag] + v) + ' '
            swapped += 1
    write(lines, 'mixed_order_bar_%dd.msh' % dim)
    print('mixed_order_bar_%dd.msh: %d of %d cells listed with two vertices swapped'
          % (dim, swapped, len(cells)))


def move_node(source, target, dim, past):
    """Moves an interior node v of a cell T to the centroid of T's opposite
    face (edge), plus 'past' times the distance beyond it (0: T becomes
    flat; > 0: T is inverted, v pushed through the face). Picks the first
    node and cell (in file order) for which no other cell changes sign or
    loses more than 95 % of its measure."""
    lines, nodes, cells = read(os.path.join(here if source.startswith('mixed') else meshes, source), dim)
    coordinate = lambda n: nodes[n][1][:dim]
    lower = [min(x[1][d] for x in nodes.values()) for d in range(dim)]
    upper = [max(x[1][d] for x in nodes.values()) for d in range(dim)]
    interior = lambda p: all(lower[d] + 1e-9 < p[d] < upper[d] - 1e-9 for d in range(dim))
    star = {}
    for c in cells:
        for n in c[2]:
            star.setdefault(n, []).append(c)
    for v in sorted(nodes):
        if v not in star or not interior(coordinate(v)):
            continue
        for (tag, line, vertices) in star[v]:
            face = [coordinate(n) for n in vertices if n != v]
            x = coordinate(v)
            # Towards the centroid of the opposite face (edge), which is
            # inside it.
            foot = [sum(q[d] for q in face) / len(face) for d in range(dim)]
            new = [foot[d] + past * (foot[d] - x[d]) for d in range(dim)]
            moved = {**{n: coordinate(n) for n in nodes}, v: new}
            changed, ok = [], True
            for (other, _, vv) in star[v]:
                before = det([coordinate(n) for n in vv])
                after = det([moved[n] for n in vv])
                if other == tag:
                    continue
                if after * before <= 0 or abs(after) < 0.05 * abs(before):
                    ok = False
            if not ok:
                continue
            if past == 0:
                changed = [tag]
            else:
                assert det([moved[n] for n in vertices]) * det([coordinate(n) for n in vertices]) < 0
                changed = [tag]
            line = nodes[v][0]
            rest = nodes[v][1][dim:]
            lines[line] = ' '.join(repr(float(q)) for q in new + rest)
            write(lines, target)
            print('%s: node %d moved from %s to %s; gmsh element %d %s'
                  % (target, v, x, new, tag, 'is flat' if past == 0 else 'is inverted'))
            return
    raise RuntimeError('no suitable node for ' + target)


mixed_order(2)
mixed_order(3)
move_node('bar_2d.msh', 'bad_folded_mesh_2d.msh', 2, 0.25)
move_node('mixed_order_bar_3d.msh', 'bad_folded_mesh_3d.msh', 3, 0.25)
move_node('bar_2d.msh', 'bad_flat_cell_mesh_2d.msh', 2, 0.)
move_node('bar_3d.msh', 'bad_flat_cell_mesh_3d.msh', 3, 0.)
