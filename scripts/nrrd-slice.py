#!/usr/bin/env python3
"""Writes plane z=K of an 8-bit NRRD volume as a PPM, each voxel an S x S block (nearest neighbour).

The gallery's honest view of the voxels themselves: no texsynth evaluation, no interpolation.
Usage: scripts/nrrd-slice.py VOLUME.nrrd K S OUT.ppm (gray and RGB, raw or gzip encoding).
"""
import gzip
import sys


def read_nrrd(path):
    with open(path, "rb") as f:
        data = f.read()
    header, _, payload = data.partition(b"\n\n")
    fields = {}
    for line in header.decode("ascii").splitlines()[1:]:
        if line.startswith("#") or ": " not in line:
            continue
        key, value = line.split(": ", 1)
        fields[key.strip()] = value.strip()
    if fields.get("type") not in ("uint8", "unsigned char", "uchar"):
        sys.exit(f"{path}: only 8-bit volumes, not {fields.get('type')}")
    if fields.get("encoding") == "gzip":
        payload = gzip.decompress(payload)
    elif fields.get("encoding") != "raw":
        sys.exit(f"{path}: unsupported encoding {fields.get('encoding')}")
    sizes = [int(s) for s in fields["sizes"].split()]
    channels = sizes[0] if len(sizes) == 4 else 1
    return sizes[-3:], channels, payload


def main():
    path, k, scale, out = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    (nx, ny, nz), channels, voxels = read_nrrd(path)
    if not 0 <= k < nz:
        sys.exit(f"{path}: plane {k} outside 0..{nz - 1}")
    rows = []
    for y in range(ny):
        row = bytearray()
        for x in range(nx):
            i = ((k * ny + y) * nx + x) * channels
            rgb = voxels[i : i + 3] if channels >= 3 else voxels[i : i + 1] * 3
            row += rgb * scale
        rows += [bytes(row)] * scale
    with open(out, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (nx * scale, ny * scale))
        f.write(b"".join(rows))


main()
