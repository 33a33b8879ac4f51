#!/usr/bin/env python3
# SPDX-License-Identifier: BSL-1.0
# Writes the seed corpus of the mesh reader fuzz targets into tests/fuzz/corpus/<format>/:
# small files covering each syntax variant (regenerate with: python3 tests/fuzz/make_corpus.py).
import os
import struct

here = os.path.dirname(os.path.abspath(__file__))
V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, 1.25)]
F = [(0, 1, 2, 3), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]


def put(fmt, name, data):
    d = os.path.join(here, "corpus", fmt)
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data if isinstance(data, bytes) else data.encode())


def obj_text(eol="\n"):
    s = ["# pyramid", "o pyramid"] + ["v %r %r %r" % v for v in V]
    s += ["vt 0 0", "vt 1 0", "vt 1 1", "vn 0 0 1"]
    s += ["f 1/1/1 2/2/1 3/3/1 4/3/1", "f 1//1 2//1 5//1", "f 2/1 3/2 5/3", "f -3 -2 -1",
          "f 4 1 5"]
    return eol.join(s) + eol


put("obj", "pyramid.obj", obj_text())
put("obj", "pyramid_crlf.obj", obj_text("\r\n"))
put("obj", "tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
put("obj", "ngon_w.obj", "v 0 0 0 1\nv 1 0 0 1\nv 1 1 0\nv 0 1 0\nv -1 .5 +0\ng a\ns off\n"
    "usemtl m\nf 1 2 3 4 5\nl 1 2\n")


def off_text(header="OFF", extra=""):
    s = [header, "# comment", "%d %d 0" % (len(V), len(F))]
    s += ["%r %r %r%s" % (v + (extra,)) for v in V]
    s += ["%d %s" % (len(f), " ".join(map(str, f))) for f in F]
    return "\n".join(s) + "\n"


put("off", "pyramid.off", off_text())
put("off", "pyramid_color.off", off_text("COFF", " 255 0 0 255"))
put("off", "noheader.off", "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
put("off", "sameline.off", "OFF 3 1 0\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2 0.5 0.5 0.5\r\n")


def ply(enc, vtype="float", ctype="uchar", itype="int", extra=True):
    head = ["ply", "format %s 1.0" % enc, "comment fuzz seed", "element vertex %d" % len(V),
            "property %s x" % vtype, "property %s y" % vtype, "property %s z" % vtype]
    if extra:
        head += ["property uchar red"]
    head += ["element face %d" % len(F),
             "property list %s %s vertex_indices" % (ctype, itype)]
    if extra:
        head += ["element edge 1", "property int a", "property int b"]
    head += ["end_header"]
    out = ("\n".join(head) + "\n").encode()
    if enc == "ascii":
        body = ["%r %r %r%s" % (v + (" 7" if extra else "",)) for v in V]
        body += ["%d %s" % (len(f), " ".join(map(str, f))) for f in F]
        if extra:
            body += ["0 1"]
        return out + ("\n".join(body) + "\n").encode()
    e = "<" if enc == "binary_little_endian" else ">"
    code = {"float": "f", "double": "d", "short": "h", "uchar": "B", "int": "i", "uint": "I",
            "ushort": "H", "char": "b"}
    for v in V:
        real = vtype in ("float", "double")
        out += struct.pack(e + code[vtype] * 3, *[float(c) if real else int(2 * c) for c in v])
        if extra:
            out += struct.pack("B", 7)
    for f in F:
        out += struct.pack(e + code[ctype], len(f)) + struct.pack(e + code[itype] * len(f), *f)
    if extra:
        out += struct.pack(e + "ii", 0, 1)
    return out


put("ply", "ascii.ply", ply("ascii"))
put("ply", "le_float.ply", ply("binary_little_endian"))
put("ply", "be_double.ply", ply("binary_big_endian", "double", "ushort", "uint", False))
put("ply", "le_short.ply", ply("binary_little_endian", "short", "uchar", "char", True))


def stl_ascii(name="pyramid"):
    s = ["solid " + name]
    for f in F:
        for i in range(1, len(f) - 1):
            s += ["facet normal 0 0 0", " outer loop"]
            s += ["  vertex %r %r %r" % V[k] for k in (f[0], f[i], f[i + 1])]
            s += [" endloop", "endfacet"]
    s += ["endsolid " + name]
    return "\n".join(s) + "\n"


def stl_binary(header=b"fuzz seed"):
    tris = [(f[0], f[i], f[i + 1]) for f in F for i in range(1, len(f) - 1)]
    out = header.ljust(80, b" ") + struct.pack("<I", len(tris))
    for t in tris:
        out += struct.pack("<3f", 0, 0, 0)
        for k in t:
            out += struct.pack("<3f", *V[k])
        out += b"\0\0"
    return out


put("stl", "ascii.stl", stl_ascii())
put("stl", "upper.stl", stl_ascii().upper().replace("\n", "\r\n"))
put("stl", "binary.stl", stl_binary())
put("stl", "binary_solid.stl", stl_binary(b"solid but binary"))
