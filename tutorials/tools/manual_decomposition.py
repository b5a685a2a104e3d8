"""constant/cellDecomposition for decomposePar's `manual` method (tutorials/tools/parallel.sh):
each cell's rank from a slanted cut across the case's long axis, so that the subdomains are not
boxes and their boundaries are not planes of the mesh (what scotch would give, which Debian's
OpenFOAM has only as a stub). Reads the cell centres of 0/C (postProcess -func writeCellCentres)
and removes 0/C*, which are only for this.

    manual_decomposition.py <ranks> <axis x|y|z>
"""
import glob
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import foamcase as fc  # noqa: E402
import numpy as np  # noqa: E402

nranks, axis = int(sys.argv[1]), "xyz".index(sys.argv[2])
C = np.asarray(fc.internal_field("0/C"))
for f in glob.glob("0/C") + glob.glob("0/C[xyz]"):
    os.remove(f)
other = (axis + 1) % 3
lo, hi = C.min(axis=0), C.max(axis=0)
span = np.where(hi > lo, hi - lo, 1.0)
# along the axis, tilted by a third of the other axis's extent: slanted, stair-stepped boundaries
t = (C[:, axis] - lo[axis]) / span[axis] + 0.35 * (C[:, other] - lo[other]) / span[other]
t = (t - t.min()) / max(t.max() - t.min(), 1e-300)
rank = np.minimum((t * nranks).astype(int), nranks - 1)
with open("constant/cellDecomposition", "w") as f:
    f.write('FoamFile { version 2.0; format ascii; class labelList; location "constant"; '
            'object cellDecomposition; }\n')
    f.write(f"{len(rank)}\n(\n")
    f.write("\n".join(str(r) for r in rank))
    f.write("\n)\n")
counts = np.bincount(rank, minlength=nranks)
print("manual decomposition (slanted cut along %s): cells per rank %s" % ("xyz"[axis], " ".join(map(str, counts))))
