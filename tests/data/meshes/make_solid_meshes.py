#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the small hand-made solid .msh files (MSH 2.2 ASCII) of tests/gmsh/test_solid_mesh_file.cpp.

Run from this directory: python3 make_solid_meshes.py. The files are committed;
this script says how they were made. The good mesh is two unit cubes along x,
[0, 2] x [0, 1] x [0, 1], hexa-8, with the physical surfaces rear (x = 0),
front (x = 2), symmetry (y = 0 and z = 0) and container (y = 1 and z = 1); each
other file changes one thing in it.
"""

REAR, FRONT, SYMMETRY, CONTAINER, DOMAIN = 1, 2, 3, 4, 10
NAMES = [(2, REAR, "rear"), (2, FRONT, "front"), (2, SYMMETRY, "symmetry"),
         (2, CONTAINER, "container"), (3, DOMAIN, "domain")]


def node(i, j, k):
    """Tag of lattice node (i, j, k) of the 3 x 2 x 2 corner lattice."""
    return 1 + i + 3 * (j + 2 * k)


def corner_nodes():
    return {node(i, j, k): (float(i), float(j), float(k))
            for k in range(2) for j in range(2) for i in range(3)}


def hex8(c):
    """Gmsh hexa-8 order: the bottom face (z = 0) counter-clockwise seen from +z, then the top."""
    return [node(c, 0, 0), node(c + 1, 0, 0), node(c + 1, 1, 0), node(c, 1, 0),
            node(c, 0, 1), node(c + 1, 0, 1), node(c + 1, 1, 1), node(c, 1, 1)]


def boundary_quads(groups=(REAR, FRONT, SYMMETRY, CONTAINER)):
    quads = []
    if REAR in groups:
        quads.append((REAR, [node(0, 0, 0), node(0, 1, 0), node(0, 1, 1), node(0, 0, 1)]))
    if FRONT in groups:
        quads.append((FRONT, [node(2, 0, 0), node(2, 1, 0), node(2, 1, 1), node(2, 0, 1)]))
    for c in range(2):
        if SYMMETRY in groups:
            quads.append((SYMMETRY, [node(c, 0, 0), node(c + 1, 0, 0), node(c + 1, 0, 1), node(c, 0, 1)]))
            quads.append((SYMMETRY, [node(c, 0, 0), node(c + 1, 0, 0), node(c + 1, 1, 0), node(c, 1, 0)]))
        if CONTAINER in groups:
            quads.append((CONTAINER, [node(c, 1, 0), node(c + 1, 1, 0), node(c + 1, 1, 1), node(c, 1, 1)]))
            quads.append((CONTAINER, [node(c, 0, 1), node(c + 1, 0, 1), node(c + 1, 1, 1), node(c, 1, 1)]))
    return quads


def write(path, nodes, volumes, quads):
    """volumes: (Gmsh type, node tags); quads: (physical tag, 4 node tags)."""
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", str(len(NAMES))]
    lines += [f'{dim} {tag} "{name}"' for dim, tag, name in NAMES]
    lines += ["$EndPhysicalNames", "$Nodes", str(len(nodes))]
    lines += [f"{tag} {x:g} {y:g} {z:g}" for tag, (x, y, z) in sorted(nodes.items())]
    lines += ["$EndNodes", "$Elements", str(len(volumes) + len(quads))]
    number = 1
    for kind, tags in volumes:  # one elementary volume per element type (Gmsh keeps one per entity)
        lines.append(" ".join(map(str, [number, kind, 2, DOMAIN, kind] + tags)))
        number += 1
    for group, tags in quads:  # one elementary surface per group
        lines.append(" ".join(map(str, [number, 3, 2, group, 100 + group] + tags)))
        number += 1
    lines.append("$EndElements")
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")


def main():
    nodes = corner_nodes()
    cubes = [(5, hex8(0)), (5, hex8(1))]
    write("solid-two-cubes.msh", nodes, cubes, boundary_quads())
    # The front face in no group: one boundary face unlabelled.
    write("solid-unlabelled-face.msh", nodes, cubes, boundary_quads((REAR, SYMMETRY, CONTAINER)))
    # Node (0, 1, 1) pulled through the opposite face of the first cube: tangled.
    tangled = dict(nodes)
    tangled[node(0, 1, 1)] = (1.5, 0.2, 0.2)
    write("solid-tangled.msh", tangled, cubes, boundary_quads())
    # The first cube mirrored (bottom and top faces swapped): left-handed but valid.
    mirrored = [(5, hex8(0)[4:] + hex8(0)[:4]), (5, hex8(1))]
    write("solid-left-handed.msh", nodes, mirrored, boundary_quads())
    # Tetrahedra: the first cube as five of them (no hexahedra needed to refuse).
    a = hex8(0)
    tets = [(4, [a[0], a[1], a[3], a[4]]), (4, [a[1], a[2], a[3], a[6]]),
            (4, [a[1], a[4], a[5], a[6]]), (4, [a[3], a[4], a[6], a[7]]),
            (4, [a[1], a[3], a[4], a[6]]), (5, hex8(1))]
    write("solid-tetrahedra.msh", nodes, tets, boundary_quads())
    # 20-node serendipity hexahedra: the mid-edge nodes, numbered after the corners.
    mids = dict(nodes)
    edges = [(0, 1), (0, 3), (0, 4), (1, 2), (1, 5), (2, 3), (2, 6), (3, 7), (4, 5), (4, 7),
             (5, 6), (6, 7)]
    serendipity, mixed = [], []
    for c in range(2):
        corners = hex8(c)
        extra = []
        for p, q in edges:
            tag = 100 + 12 * c + len(extra)
            mids[tag] = tuple((u + v) / 2 for u, v in zip(nodes[corners[p]], nodes[corners[q]]))
            extra.append(tag)
        serendipity.append((17, corners + extra))
    write("solid-hexa20.msh", mids, serendipity, boundary_quads())
    # One hexa-8 and one hexa-27 (its face and centre nodes added): mixed orders.
    faces = [(0, 1, 2, 3), (0, 1, 5, 4), (0, 3, 7, 4), (1, 2, 6, 5), (2, 3, 7, 6), (4, 5, 6, 7)]
    full = dict(mids)
    corners = hex8(1)
    inner = []
    for face in faces:
        tag = 200 + len(inner)
        full[tag] = tuple(sum(nodes[corners[p]][d] for p in face) / 4 for d in range(3))
        inner.append(tag)
    full[300] = (1.5, 0.5, 0.5)
    mixed = [(5, hex8(0)), (12, corners + serendipity[1][1][8:] + inner + [300])]
    write("solid-mixed-orders.msh", full, mixed, boundary_quads())


if __name__ == "__main__":
    main()
