// SPDX-License-Identifier: BSL-1.0
// Tests of io/mesh_io.hpp. Round trips write -> read in every format compare the meshes bit for
// bit (STL: the triangles' corner coordinates, rounded to float for binary STL); hand-written
// files cover each syntax variant with the values written in them; binary files are assembled
// byte by byte here, independently of the writer; hostile files (huge counts, indices out of
// range, NaN, truncation at every byte) must give the documented status, never a crash or a
// huge allocation (the sanitizer build aborts on one).

#include <locus/io/mesh_io.hpp>

#include "support/typed.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/stat.h>
#endif

namespace {

using locus::MeshFormat;
using locus::PolygonMesh;
using locus::Status;

template <class T>
class MeshIoTest : public ::testing::Test {};
TYPED_TEST_SUITE(MeshIoTest, locus_test::RealTypes);

template <class T>
std::vector<std::vector<std::uint32_t>> faces_of(const PolygonMesh<T>& m) {
  std::vector<std::vector<std::uint32_t>> out;
  for (std::size_t f = 0; f < locus::face_count(m); ++f) {
    const auto v = locus::face(m, f);
    out.emplace_back(v.begin(), v.end());
  }
  return out;
}

template <class T>
bool same_bits(const locus::Vec3<T>& a, const locus::Vec3<T>& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

template <class T>
void expect_same_mesh(const PolygonMesh<T>& a, const PolygonMesh<T>& b) {
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (std::size_t i = 0; i < a.vertices.size(); ++i) {
    EXPECT_TRUE(same_bits(a.vertices[i], b.vertices[i]))
        << "vertex " << i << ": " << a.vertices[i].x << " " << a.vertices[i].y << " "
        << a.vertices[i].z << " vs " << b.vertices[i].x << " " << b.vertices[i].y << " "
        << b.vertices[i].z;
  }
  EXPECT_EQ(a.face_offsets, b.face_offsets);
  EXPECT_EQ(a.face_indices, b.face_indices);
}

// A random mesh with awkward coordinates (subnormals, huge and tiny magnitudes, negative zero,
// values with long shortest representations) and faces of 3 to 300 vertices.
template <class T>
PolygonMesh<T> random_mesh(locus_test::Rng& rng, int nv, int nf, int max_face = 8) {
  PolygonMesh<T> m;
  const T specials[] = {T(0),
                        -T(0),
                        std::numeric_limits<T>::denorm_min(),
                        -std::numeric_limits<T>::min(),
                        std::numeric_limits<T>::max(),
                        std::numeric_limits<T>::lowest(),
                        T(0.1),
                        T(1) / T(3)};
  std::vector<T> pool;
  for (int i = 0; i < 3 * nv; ++i) {
    const int kind = rng.uniform_int(0, 9);
    T x;
    if (kind == 0) {
      x = specials[std::size_t(rng.uniform_int(0, 7))];
    } else if (kind == 1) {
      x = std::ldexp(rng.uniform(T(-1), T(1)), rng.uniform_int(-120, 120));
    } else {
      x = rng.uniform(T(-1000), T(1000));
    }
    pool.push_back(x);
  }
  for (int i = 0; i < nv; ++i) {
    m.vertices.push_back(
        {pool[std::size_t(3 * i)], pool[std::size_t(3 * i + 1)], pool[std::size_t(3 * i + 2)]});
  }
  for (int f = 0; f < nf; ++f) {
    std::vector<std::uint32_t> fv(std::size_t(rng.uniform_int(3, max_face)));
    for (auto& i : fv) i = std::uint32_t(rng.uniform_int(0, nv - 1));
    locus::add_face(m, std::span<const std::uint32_t>(fv));
  }
  return m;
}

// The corner coordinates of every fan triangle, as STL stores them.
template <class T>
std::vector<locus::Vec3<T>> corners(const PolygonMesh<T>& m, bool to_float) {
  std::vector<locus::Vec3<T>> out;
  for (const auto& t : locus::fan_triangles(m)) {
    for (const auto i : t) {
      locus::Vec3<T> v = m.vertices[i];
      if (to_float) {
        for (int k = 0; k < 3; ++k) v[k] = T(float(v[k]));
      }
      out.push_back(v);
    }
  }
  return out;
}

constexpr MeshFormat exact_formats[] = {MeshFormat::obj, MeshFormat::off, MeshFormat::ply_ascii,
                                        MeshFormat::ply_binary_le, MeshFormat::ply_binary_be};

TYPED_TEST(MeshIoTest, RoundTripIsBitExact) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    const PolygonMesh<T> m =
        random_mesh<T>(rng, rng.uniform_int(1, 200), rng.uniform_int(0, 100), trial % 4 ? 8 : 300);
    for (const MeshFormat f : exact_formats) {
      SCOPED_TRACE(static_cast<int>(f));
      const auto w = locus::write_mesh_string(m, f);
      ASSERT_EQ(w.status, Status::ok) << w.message;
      const auto r = locus::parse_mesh<T>(w.data, f, "round.trip");
      ASSERT_EQ(r.status, Status::ok) << r.message;
      expect_same_mesh(m, r.mesh);
    }
  }
}

TYPED_TEST(MeshIoTest, StlRoundTripKeepsEveryCorner) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 20; ++trial) {
    PolygonMesh<T> m = random_mesh<T>(rng, rng.uniform_int(3, 100), rng.uniform_int(1, 60));
    // Binary STL stores float: keep the coordinates within its range.
    for (auto& v : m.vertices) {
      for (int k = 0; k < 3; ++k) {
        if (!(std::fabs(v[k]) < T(1e30))) v[k] = T(1e30);
      }
    }
    for (const MeshFormat f : {MeshFormat::stl_ascii, MeshFormat::stl_binary}) {
      const bool binary = f == MeshFormat::stl_binary;
      const auto w = locus::write_mesh_string(m, f);
      ASSERT_EQ(w.status, Status::ok) << w.message;
      const auto r = locus::parse_mesh<T>(w.data, MeshFormat::stl, "x.stl");
      ASSERT_EQ(r.status, Status::ok) << r.message;
      const auto a = corners(m, binary), b = corners(r.mesh, false);
      ASSERT_EQ(a.size(), b.size());
      for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(same_bits(a[i], b[i])) << i;
      // Corners are merged: no two vertices share their bits.
      for (std::size_t i = 0; i < r.mesh.vertices.size(); ++i) {
        for (std::size_t j = i + 1; j < r.mesh.vertices.size(); ++j) {
          ASSERT_FALSE(same_bits(r.mesh.vertices[i], r.mesh.vertices[j]));
        }
      }
    }
  }
}

TYPED_TEST(MeshIoTest, FilesByExtension) {
  using T = TypeParam;
  locus_test::Rng rng;
  const PolygonMesh<T> m = random_mesh<T>(rng, 30, 20);
  const auto dir = std::filesystem::temp_directory_path() /
                   ("locus_mesh_io_" + std::to_string(sizeof(T)) + "_" +
                    std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::create_directories(dir);
  for (const char* name : {"a.obj", "b.OFF", "c.ply", "d.Ply"}) {
    const auto path = dir / name;
    const auto w = locus::write_mesh(path, m);
    ASSERT_EQ(w.status, Status::ok) << w.message;
    const auto r = locus::read_mesh<T>(path);
    ASSERT_EQ(r.status, Status::ok) << r.message;
    expect_same_mesh(m, r.mesh);
  }
  // .ply writes binary little endian, .stl binary.
  {
    std::ifstream in(dir / "c.ply", std::ios::binary);
    std::string head(60, '\0');
    in.read(head.data(), 60);
    EXPECT_NE(head.find("format binary_little_endian 1.0"), std::string::npos);
  }
  PolygonMesh<T> small = m;  // within binary STL's float range
  for (auto& v : small.vertices) {
    for (int k = 0; k < 3; ++k) v[k] = std::fmod(v[k], T(1e6));
  }
  ASSERT_EQ(locus::write_mesh(dir / "e.stl", small).status, Status::ok);
  EXPECT_EQ(std::filesystem::file_size(dir / "e.stl"), 84 + 50 * locus::fan_triangle_count(m));
  const auto s = locus::read_mesh<T>(dir / "e.stl");
  ASSERT_EQ(s.status, Status::ok) << s.message;
  EXPECT_EQ(locus::fan_triangle_count(s.mesh), locus::fan_triangle_count(m));
  // An override beats the extension.
  ASSERT_EQ(locus::write_mesh(dir / "f.txt", m, MeshFormat::off).status, Status::ok);
  const auto o = locus::read_mesh<T>(dir / "f.txt", MeshFormat::off);
  ASSERT_EQ(o.status, Status::ok) << o.message;
  expect_same_mesh(m, o.mesh);
  EXPECT_EQ(locus::read_mesh<T>(dir / "f.txt").status, Status::invalid_input);
  EXPECT_EQ(locus::write_mesh(dir / "g.xyz", m).status, Status::invalid_input);
  const auto missing = locus::read_mesh<T>(dir / "missing.obj");
  EXPECT_EQ(missing.status, Status::io_error);
  EXPECT_NE(missing.message.find("missing.obj"), std::string::npos);
  EXPECT_EQ(locus::write_mesh(dir / "no_such_dir" / "x.obj", m).status, Status::io_error);
  std::filesystem::create_directories(dir / "dir.obj");
  EXPECT_EQ(locus::read_mesh<T>(dir / "dir.obj").status, Status::io_error);
  { std::ofstream empty(dir / "empty.obj"); }
  const auto e = locus::read_mesh<T>(dir / "empty.obj");
  EXPECT_EQ(e.status, Status::ok) << e.message;
  EXPECT_EQ(locus::read_mesh<T>(dir / "empty.obj", MeshFormat::ply).status, Status::parse_error);
  std::filesystem::remove_all(dir);
}

// read_mesh reads regular files only, taking the type from the open descriptor: a FIFO without
// a writer must not block (it is opened non-blocking), a device has no length to read up to; a
// symbolic link to a regular file is followed.
TYPED_TEST(MeshIoTest, SpecialFilesGiveAnIoError) {
  using T = TypeParam;
  locus_test::Rng rng;
  const PolygonMesh<T> m = random_mesh<T>(rng, 12, 8);
  const auto dir = std::filesystem::temp_directory_path() /
                   ("locus_mesh_io_special_" + std::to_string(sizeof(T)) + "_" +
                    std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::create_directories(dir);
  const auto expect_refused = [](const std::filesystem::path& path) {
    const auto r = locus::read_mesh<T>(path, MeshFormat::obj);
    EXPECT_EQ(r.status, Status::io_error) << path;
    EXPECT_EQ(r.message, path.string() + ": cannot read the file (not a regular file)");
  };
  if (std::filesystem::exists("/dev/null")) expect_refused("/dev/null");
  if (std::filesystem::exists("/dev/zero")) expect_refused("/dev/zero");
  expect_refused(dir);
#if defined(__unix__) || defined(__APPLE__)
  const auto fifo = dir / "fifo.obj";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_refused(fifo);
#endif
  ASSERT_EQ(locus::write_mesh(dir / "a.off", m).status, Status::ok);
  std::error_code ec;
  std::filesystem::create_symlink(dir / "a.off", dir / "link.off", ec);
  if (!ec) {
    const auto r = locus::read_mesh<T>(dir / "link.off");
    ASSERT_EQ(r.status, Status::ok) << r.message;
    expect_same_mesh(m, r.mesh);
  }
  const auto missing = locus::read_mesh<T>(dir / "missing.off");
  EXPECT_EQ(missing.status, Status::io_error);
  EXPECT_EQ(missing.message.rfind((dir / "missing.off").string() + ": cannot open the file", 0), 0u)
      << missing.message;
  std::filesystem::remove_all(dir);
}

TEST(MeshIo, FormatFromName) {
  EXPECT_EQ(locus::mesh_format_from_name("a/b.c/mesh.OBJ"), MeshFormat::obj);
  EXPECT_EQ(locus::mesh_format_from_name("x.off"), MeshFormat::off);
  EXPECT_EQ(locus::mesh_format_from_name("x.pLy"), MeshFormat::ply);
  EXPECT_EQ(locus::mesh_format_from_name("x.stl"), MeshFormat::stl);
  EXPECT_EQ(locus::mesh_format_from_name("x.stlx"), MeshFormat::from_extension);
  EXPECT_EQ(locus::mesh_format_from_name("dir.obj/file"), MeshFormat::from_extension);
  EXPECT_EQ(locus::mesh_format_from_name("obj"), MeshFormat::from_extension);
}

TYPED_TEST(MeshIoTest, WriterRefusesMalformedMeshes) {
  using T = TypeParam;
  PolygonMesh<T> m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.face_offsets = {0, 3};
  m.face_indices = {0, 1, 3};
  for (const MeshFormat f : exact_formats) {
    const auto w = locus::write_mesh_string(m, f);
    EXPECT_EQ(w.status, Status::invalid_input);
    EXPECT_TRUE(w.data.empty());
  }
  m.face_indices = {0, 1, 2};
  m.vertices[1].x = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(locus::write_mesh_string(m, MeshFormat::obj).status, Status::non_finite_input);
  m.vertices[1].x = 1;
  EXPECT_EQ(locus::write_mesh_string(m, MeshFormat::from_extension).status, Status::invalid_input);
  if constexpr (std::is_same_v<T, double>) {
    m.vertices[1].x = 1e300;  // not representable in binary STL's float
    EXPECT_EQ(locus::write_mesh_string(m, MeshFormat::stl_binary).status, Status::non_finite_input);
    EXPECT_EQ(locus::write_mesh_string(m, MeshFormat::stl_ascii).status, Status::ok);
  }
}

// ---- hand-written files -------------------------------------------------------------------

template <class T>
locus::MeshReadResult<T> parse(std::string_view text, MeshFormat f, std::string_view name = "t") {
  return locus::parse_mesh<T>(text, f, name);
}

template <class T>
locus::Vec3<T> v3(double x, double y, double z) {
  return {T(x), T(y), T(z)};
}

TYPED_TEST(MeshIoTest, ObjSyntaxVariants) {
  using T = TypeParam;
  const std::string text =
      "# a comment\r\n"
      "mtllib x.mtl\r\n"
      "o thing\r\n"
      "v 0 0 0\r\n"
      "v 1.5 0 0 1.0\r\n"         // w ignored
      "v +1 1 0 0.5 0.5 0.5\r\n"  // colours ignored
      "v 0 1e2 -0.25   # trailing comment\r\n"
      "\r\n"
      "vt 0 0\nvt 1 0\nvt 1 1\n"
      "vn 0 0 1\n"
      "g group\ns 1\nusemtl m\n"
      "f 1 2 3\n"
      "f 1/1 2/2 3/3\n"
      "f 1//1 3//1 4//1\n"
      "f 1/1/1 2/2/1 3/3/1 4/3/1\n"
      "f -4 -3 -2 -1\n"
      "f\t1 2   3 4  \n"
      "l 1 2\n"
      "f 1 2 5\n"  // forward reference: vertex 5 is defined below
      "v 2 2 2\n";
  const auto r = parse<T>(text, MeshFormat::obj);
  ASSERT_EQ(r.status, Status::ok) << r.message;
  const std::vector<locus::Vec3<T>> v = {v3<T>(0, 0, 0), v3<T>(1.5, 0, 0), v3<T>(1, 1, 0),
                                         v3<T>(0, 100, -0.25), v3<T>(2, 2, 2)};
  ASSERT_EQ(r.mesh.vertices.size(), v.size());
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_TRUE(same_bits(r.mesh.vertices[i], v[i]));
  const std::vector<std::vector<std::uint32_t>> f = {
      {0, 1, 2}, {0, 1, 2}, {0, 2, 3}, {0, 1, 2, 3}, {0, 1, 2, 3}, {0, 1, 2, 3}, {0, 1, 4}};
  EXPECT_EQ(faces_of(r.mesh), f);
  // An empty file is an empty mesh.
  const auto e = parse<T>("", MeshFormat::obj);
  EXPECT_EQ(e.status, Status::ok);
  EXPECT_TRUE(e.mesh.vertices.empty());
}

// OBJ files written here with every corner form and a random mix of absolute and relative
// indices, vertices interleaved with faces (relative indices count only the vertices above):
// the reader must give back the mesh they were written from.
TYPED_TEST(MeshIoTest, ObjRelativeAndAbsoluteIndicesAgree) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  for (int trial = 0; trial < 30; ++trial) {
    const PolygonMesh<T> m = random_mesh<T>(rng, rng.uniform_int(3, 40), rng.uniform_int(1, 30));
    std::string text;
    std::size_t written = 0;  // vertices written so far
    for (std::size_t f = 0; f < locus::face_count(m); ++f) {
      const auto fv = locus::face(m, f);
      const std::uint32_t need = *std::max_element(fv.begin(), fv.end()) + 1;
      for (; written < need; ++written) {
        const auto& v = m.vertices[written];
        char buf[128];
        std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\nvt 0 0\nvn 0 0 1\n", double(v.x),
                      double(v.y), double(v.z));
        text += buf;
      }
      text += rng.uniform_int(0, 1) ? "f" : "f ";
      for (const std::uint32_t i : fv) {
        const bool relative = rng.uniform_int(0, 1) != 0;
        const std::string idx = relative ? std::to_string(std::int64_t(i) - std::int64_t(written))
                                         : std::to_string(i + 1);
        const std::string forms[] = {idx, idx + "/" + idx, idx + "//" + idx,
                                     idx + "/" + idx + "/" + idx};
        text += " " + forms[rng.uniform_int(0, 3)];
      }
      text += rng.uniform_int(0, 1) ? "\n" : "\r\n";
    }
    for (; written < m.vertices.size(); ++written) {
      const auto& v = m.vertices[written];
      char buf[128];
      std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", double(v.x), double(v.y),
                    double(v.z));
      text += buf;
    }
    // Read through the byte-span overload.
    const auto r = locus::parse_mesh<T>(std::as_bytes(std::span(text.data(), text.size())),
                                        MeshFormat::obj, "mixed.obj");
    ASSERT_EQ(r.status, Status::ok) << r.message;
    expect_same_mesh(m, r.mesh);  // %.17g reads back exactly in float and double
  }
}

TYPED_TEST(MeshIoTest, OffSyntaxVariants) {
  using T = TypeParam;
  const std::vector<std::vector<std::uint32_t>> quad_tri = {{0, 1, 2, 3}, {0, 2, 4}};
  const std::vector<locus::Vec3<T>> v = {v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(1, 1, 0),
                                         v3<T>(0, 1, 0), v3<T>(0.5, 0.5, 1)};
  const char* files[] = {
      "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n4 0 1 2 3\n3 0 2 4\n",
      // no header, comments, blank lines, CRLF
      "# made by hand\r\n\r\n5 2 6\r\n0 0 0\r\n1 0 0 # x\r\n1 1 0\r\n0 1 0\r\n0.5 0.5 "
      "1\r\n\r\n4 0 1 2 3\r\n3 0 2 4\r\n",
      // counts on the header line
      "OFF 5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n4 0 1 2 3\n3 0 2 4\n",
      // colours per vertex and per face, normals
      "CNOFF\n5 2 0\n0 0 0 0 0 1 255 0 0 255\n1 0 0 0 0 1 0 255 0 255\n1 1 0 0 0 1 0 0 255 "
      "255\n0 1 0 0 0 1 1 1 1 1\n0.5 0.5 1 0 0 1 1 1 1 1\n4 0 1 2 3 255 0 0\n3 0 2 4 0.5 0.5 "
      "0.5 1\n",
      // edge count omitted, trailing data after the faces
      "OFF\n5 2\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n4 0 1 2 3\n3 0 2 4\n2 0 1\n"};
  for (const char* text : files) {
    SCOPED_TRACE(text);
    const auto r = parse<T>(text, MeshFormat::off);
    ASSERT_EQ(r.status, Status::ok) << r.message;
    ASSERT_EQ(r.mesh.vertices.size(), v.size());
    for (std::size_t i = 0; i < v.size(); ++i) EXPECT_TRUE(same_bits(r.mesh.vertices[i], v[i]));
    EXPECT_EQ(faces_of(r.mesh), quad_tri);
  }
  for (const char* bad : {"4OFF\n1 0 0\n0 0 0 0\n", "nOFF\n3\n1 0 0\n0 0 0\n", "OFF BINARY\n",
                          "ZOFF\n0 0 0\n", "OFF\n", "", "ply\n"}) {
    SCOPED_TRACE(bad);
    EXPECT_EQ(parse<T>(bad, MeshFormat::off).status, Status::parse_error);
  }
}

// Little helper to assemble binary files byte by byte.
struct Bytes {
  std::string s;
  bool big = false;
  template <class U>
  Bytes& put(U u) {
    char b[sizeof(U)];
    std::memcpy(b, &u, sizeof(U));
    if (big != (std::endian::native == std::endian::big)) std::reverse(b, b + sizeof(U));
    s.append(b, sizeof(U));
    return *this;
  }
  Bytes& text(std::string_view t) {
    s += t;
    return *this;
  }
};

TYPED_TEST(MeshIoTest, PlyAsciiWithExtraElementsAndProperties) {
  using T = TypeParam;
  const std::string text =
      "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info nothing\r\n"
      "element vertex 4\r\nproperty float nx\r\nproperty double x\r\nproperty uchar red\r\n"
      "property list uchar float weights\r\nproperty int y\r\nproperty float z\r\n"
      "element face 2\r\nproperty uchar flags\r\nproperty list uint8 int32 vertex_index\r\n"
      "property list uchar float texcoord\r\n"
      "element edge 1\r\nproperty int vertex1\r\nproperty int vertex2\r\nend_header\r\n"
      "0.5 0 255 2 0.1 0.2 0 0\r\n0 1 1 0 0 0\r\n0 1 1 1 0.5 1 -2.5\r\n9 0 1 3 1 2 3 1 1e-3\r\n"
      "7 3 0 1 2 0\n1 4 0 1 2 3 6 0 0 1 0 1 1\n"
      "0 1\n";
  const auto r = parse<T>(text, MeshFormat::ply);
  ASSERT_EQ(r.status, Status::ok) << r.message;
  const std::vector<locus::Vec3<T>> v = {v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(1, 1, -2.5),
                                         v3<T>(0, 1, T(1e-3))};
  ASSERT_EQ(r.mesh.vertices.size(), v.size());
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_TRUE(same_bits(r.mesh.vertices[i], v[i]));
  const std::vector<std::vector<std::uint32_t>> f = {{0, 1, 2}, {0, 1, 2, 3}};
  EXPECT_EQ(faces_of(r.mesh), f);
}

// A binary PLY with coordinates of mixed types, an extra element before the vertices, the face
// list with ushort counts and uint16 indices, and an unknown list property.
std::string binary_ply(bool big) {
  Bytes b;
  b.big = big;
  b.text("ply\nformat ").text(big ? "binary_big_endian" : "binary_little_endian");
  b.text(
      " 1.0\nelement material 2\nproperty uchar a\nproperty list uchar short b\n"
      "element vertex 4\nproperty double x\nproperty short y\nproperty uchar q\n"
      "property float z\nelement face 2\nproperty list ushort uint16 vertex_indices\n"
      "property list int float uv\nend_header\n");
  b.put<std::uint8_t>(1).put<std::uint8_t>(2).put<std::int16_t>(-1).put<std::int16_t>(7);
  b.put<std::uint8_t>(3).put<std::uint8_t>(0);
  const double xs[] = {0.1, -2.0, 1e300, 0.0};
  const std::int16_t ys[] = {-32768, 2, 3, 32767};
  const float zs[] = {0.5f, -0.0f, std::numeric_limits<float>::denorm_min(), 3e38f};
  for (int i = 0; i < 4; ++i) b.put(xs[i]).put(ys[i]).put<std::uint8_t>(9).put(zs[i]);
  b.put<std::uint16_t>(3).put<std::uint16_t>(0).put<std::uint16_t>(1).put<std::uint16_t>(2);
  b.put<std::int32_t>(2).put(0.5f).put(0.25f);
  b.put<std::uint16_t>(4).put<std::uint16_t>(3).put<std::uint16_t>(2).put<std::uint16_t>(1);
  b.put<std::uint16_t>(0).put<std::int32_t>(0);
  return b.s;
}

TYPED_TEST(MeshIoTest, PlyBinaryBothEndiansAnyTypes) {
  using T = TypeParam;
  for (const bool big : {false, true}) {
    const std::string file = binary_ply(big);
    const auto r = parse<T>(file, MeshFormat::ply);
    if constexpr (std::is_same_v<T, float>) {
      // 1e300 does not fit in a float.
      EXPECT_EQ(r.status, Status::non_finite_input) << r.message;
      continue;
    }
    ASSERT_EQ(r.status, Status::ok) << r.message;
    const std::vector<locus::Vec3<T>> v = {
        v3<T>(0.1, -32768, 0.5), v3<T>(-2.0, 2, -0.0),
        v3<T>(1e300, 3, std::numeric_limits<float>::denorm_min()), v3<T>(0.0, 32767, 3e38f)};
    ASSERT_EQ(r.mesh.vertices.size(), v.size());
    for (std::size_t i = 0; i < v.size(); ++i) EXPECT_TRUE(same_bits(r.mesh.vertices[i], v[i]));
    const std::vector<std::vector<std::uint32_t>> f = {{0, 1, 2}, {3, 2, 1, 0}};
    EXPECT_EQ(faces_of(r.mesh), f);
    // Every truncation of the body is a parse_error naming a byte offset inside the file.
    const std::size_t body = file.find("end_header\n") + 11;
    for (std::size_t n = 0; n < file.size(); ++n) {
      const auto t = parse<T>(std::string_view(file).substr(0, n), MeshFormat::ply, "cut.ply");
      ASSERT_EQ(t.status, Status::parse_error) << n;
      if (n >= body) {
        EXPECT_EQ(t.line, 0u);
        EXPECT_LE(t.byte_offset, n);
        EXPECT_EQ(t.message.rfind("cut.ply: byte ", 0), 0u) << t.message;
      }
    }
  }
}

TYPED_TEST(MeshIoTest, StlSyntaxVariants) {
  using T = TypeParam;
  const std::string ascii =
      "SOLID cube part\r\n  FACET NORMAL 0 0 1\r\n    OUTER LOOP\r\n"
      "      VERTEX 0 0 0\r\n      VERTEX 1 0 0\r\n      VERTEX 1 1 0\r\n"
      "    ENDLOOP\r\n  ENDFACET\r\nENDSOLID cube part\r\n"
      "solid second\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 1 0\n"
      "vertex 0 1 0.5\nendloop\nendfacet\nendsolid\n";
  const auto r = parse<T>(ascii, MeshFormat::stl);
  ASSERT_EQ(r.status, Status::ok) << r.message;
  const std::vector<locus::Vec3<T>> v = {v3<T>(0, 0, 0), v3<T>(1, 0, 0), v3<T>(1, 1, 0),
                                         v3<T>(0, 1, 0.5)};
  ASSERT_EQ(r.mesh.vertices.size(), v.size());
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_TRUE(same_bits(r.mesh.vertices[i], v[i]));
  const std::vector<std::vector<std::uint32_t>> f = {{0, 1, 2}, {0, 2, 3}};
  EXPECT_EQ(faces_of(r.mesh), f);

  // A binary file whose header starts with "solid" is told apart by its size.
  Bytes b;
  b.text("solid but binary");
  b.s.resize(80, ' ');
  b.put<std::uint32_t>(2);
  const float tri[2][9] = {{0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 0, 1, 1, 0, 0, 1, 0.5f}};
  for (const auto& t : tri) {
    b.put(0.f).put(0.f).put(1.f);
    for (const float x : t) b.put(x);
    b.put<std::uint16_t>(0);
  }
  const auto s = parse<T>(b.s, MeshFormat::stl);
  ASSERT_EQ(s.status, Status::ok) << s.message;
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_TRUE(same_bits(s.mesh.vertices[i], v[i]));
  EXPECT_EQ(faces_of(s.mesh), f);
  // Every truncation of the binary file fails, with a byte offset.
  for (std::size_t n = 0; n < b.s.size(); ++n) {
    const auto t = parse<T>(std::string_view(b.s).substr(0, n), MeshFormat::stl_binary);
    ASSERT_EQ(t.status, Status::parse_error) << n;
    EXPECT_EQ(t.line, 0u);
  }
  // Forcing ASCII on it fails cleanly (there is no "facet").
  EXPECT_EQ(parse<T>(b.s, MeshFormat::stl_ascii).status, Status::parse_error);
}

// ---- errors and hostile files ---------------------------------------------------------------

struct Bad {
  MeshFormat format;
  std::string text;
  Status status;
  std::size_t line;  // 0: binary, not checked
};

TYPED_TEST(MeshIoTest, HostileAndMalformedFiles) {
  using T = TypeParam;
  const std::string ply_head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\n";
  const std::vector<Bad> cases = {
      // indices out of range, zero, before the start
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n", Status::parse_error, 4},
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", Status::parse_error, 4},
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", Status::parse_error, 4},
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -9223372036854775808\n",
       Status::parse_error, 4},
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n",
       Status::parse_error, 4},
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/4 2/1 3/1\nvt 0 0\n", Status::parse_error,
       4},
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n", Status::parse_error, 4},
      // malformed corners and statements
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", Status::parse_error, 4},
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/ 2 3\n", Status::parse_error, 4},
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", Status::parse_error, 4},
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1// 2 3\n", Status::parse_error, 4},
      {MeshFormat::obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf a b c\n", Status::parse_error, 4},
      {MeshFormat::obj, "v 0 0\n", Status::parse_error, 1},
      {MeshFormat::obj, "v 0 0 0x1\n", Status::parse_error, 1},
      {MeshFormat::obj,
       "\n\nv 0 0 0\n\x7f"
       "ELF" +
           std::string(2, '\0') + "\n",
       Status::parse_error, 4},
      // non-finite coordinates
      {MeshFormat::obj, "v 0 nan 0\n", Status::non_finite_input, 1},
      {MeshFormat::obj, "v 0 0 -inf\n", Status::non_finite_input, 1},
      {MeshFormat::obj, "v 0 0 1e400\n", Status::non_finite_input, 1},
      {MeshFormat::off, "OFF\n1 0 0\nNaN 0 0\n", Status::non_finite_input, 3},
      {MeshFormat::ply, ply_head + "end_header\n0 0 0\n1 nan 0\n0 1 0\n", Status::non_finite_input,
       9},
      {MeshFormat::stl,
       "solid\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex inf 0 "
       "0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n",
       Status::non_finite_input, 5},
      // huge counts announced in a small file
      {MeshFormat::off, "OFF\n3 1000000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       Status::parse_error, 2},
      {MeshFormat::off, "OFF\n5000000000 1 0\n0 0 0\n", Status::parse_error, 2},
      {MeshFormat::off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1000000000 0 1 2\n", Status::parse_error,
       6},
      {MeshFormat::off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", Status::parse_error, 6},
      {MeshFormat::off, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", Status::parse_error, 6},
      {MeshFormat::off, "OFF\n3 1 0\n0 0 0\n1 0 0\n", Status::parse_error, 4},
      {MeshFormat::off, "OFF\n-3 1 0\n", Status::parse_error, 2},
      {MeshFormat::ply,
       ply_head + "element face 1000000000000\nproperty list uchar int "
                  "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       Status::parse_error, 7},
      {MeshFormat::ply,
       "ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float x\nproperty float "
       "y\nproperty float z\nend_header\n0 0 0\n",
       Status::parse_error, 3},
      {MeshFormat::ply,
       ply_head + "element face 1\nproperty list uint int "
                  "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                  "1000000000 0 1 2\n",
       Status::parse_error, 13},
      {MeshFormat::ply,
       ply_head + "element face 1\nproperty list uchar int "
                  "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
       Status::parse_error, 13},
      {MeshFormat::ply,
       ply_head + "element face 1\nproperty list uchar int "
                  "vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n",
       Status::parse_error, 13},
      // malformed PLY headers
      {MeshFormat::ply, "ply\nformat ascii 1.0\nproperty float x\nend_header\n",
       Status::parse_error, 3},
      {MeshFormat::ply, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n",
       Status::parse_error, 3},
      {MeshFormat::ply, ply_head + "element face 1\nproperty list float int vertex_indices\n",
       Status::parse_error, 8},
      {MeshFormat::ply,
       ply_head + "element face 1\nproperty list uchar float vertex_indices\n"
                  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       Status::parse_error, 7},
      {MeshFormat::ply, ply_head + "property quad w\nend_header\n", Status::parse_error, 7},
      {MeshFormat::ply, ply_head + "end_header", Status::parse_error, 3},
      {MeshFormat::ply, ply_head, Status::parse_error, 6},
      {MeshFormat::ply, "ply\nformat binary_middle_endian 1.0\n", Status::parse_error, 2},
      {MeshFormat::ply, "plyx\n", Status::parse_error, 1},
      {MeshFormat::ply, "", Status::parse_error, 0},
      // STL structure
      {MeshFormat::stl_ascii,
       "solid\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 "
       "0\nendloop\nendfacet\nendsolid\n",
       Status::parse_error, 6},
      {MeshFormat::stl_ascii, "solid\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\n",
       Status::parse_error, 4},
      {MeshFormat::stl_ascii, "solid x\n", Status::parse_error, 1},
  };
  for (const Bad& c : cases) {
    SCOPED_TRACE(c.text);
    const auto r = parse<T>(c.text, c.format, "bad.file");
    ASSERT_EQ(r.status, c.status) << r.message;
    if (c.line > 0) {
      EXPECT_EQ(r.line, c.line) << r.message;
      EXPECT_EQ(r.message.rfind("bad.file:" + std::to_string(c.line) + ": ", 0), 0u) << r.message;
    }
    EXPECT_GT(r.message.size(), std::string("bad.file:1: ").size());
  }
}

TYPED_TEST(MeshIoTest, HostileBinaryCounts) {
  using T = TypeParam;
  // A binary PLY announcing 10^12 faces, 2^32 - 1 vertices, and a face of 10^9 vertices.
  for (const bool big : {false, true}) {
    const std::string head = std::string("ply\nformat ") +
                             (big ? "binary_big_endian" : "binary_little_endian") + " 1.0\n";
    Bytes a;
    a.big = big;
    a.text(head +
           "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 1000000000000\nproperty list uchar int vertex_indices\nend_header\n");
    for (int i = 0; i < 9; ++i) a.put(float(i));
    a.put<std::uint8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
    EXPECT_EQ(parse<T>(a.s, MeshFormat::ply).status, Status::parse_error);
    Bytes b;
    b.big = big;
    b.text(head +
           "element vertex 4294967295\nproperty float x\nproperty float y\nproperty float "
           "z\nend_header\n");
    for (int i = 0; i < 9; ++i) b.put(float(i));
    EXPECT_EQ(parse<T>(b.s, MeshFormat::ply).status, Status::parse_error);
    Bytes c;
    c.big = big;
    c.text(head +
           "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 1\nproperty list uint int vertex_indices\nend_header\n");
    for (int i = 0; i < 9; ++i) c.put(float(i));
    c.put<std::uint32_t>(1000000000).put<std::int32_t>(0).put<std::int32_t>(1);
    const auto rc = parse<T>(c.s, MeshFormat::ply);
    EXPECT_EQ(rc.status, Status::parse_error);
    EXPECT_EQ(rc.byte_offset, c.s.size() - 12) << rc.message;
    Bytes d;  // index out of range, negative list length, NaN
    d.big = big;
    d.text(head +
           "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 1\nproperty list char int vertex_indices\nend_header\n");
    for (int i = 0; i < 9; ++i) d.put(float(i));
    Bytes d1 = d, d2 = d, d3 = d;
    d1.put<std::int8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(3);
    EXPECT_EQ(parse<T>(d1.s, MeshFormat::ply).status, Status::parse_error);
    d2.put<std::int8_t>(-3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
    EXPECT_EQ(parse<T>(d2.s, MeshFormat::ply).status, Status::parse_error);
    d3.s.replace(d3.s.size() - 4, 4, 4, '\xff');  // z of the last vertex: a NaN pattern
    d3.put<std::int8_t>(3).put<std::int32_t>(0).put<std::int32_t>(1).put<std::int32_t>(2);
    EXPECT_EQ(parse<T>(d3.s, MeshFormat::ply).status, Status::non_finite_input);
  }
  // A binary STL announcing 10^9 triangles in 184 bytes.
  Bytes s;
  s.s.assign(80, ' ');
  s.put<std::uint32_t>(1000000000);
  s.s.append(100, '\0');
  const auto r = parse<T>(s.s, MeshFormat::stl);
  EXPECT_EQ(r.status, Status::parse_error);
  EXPECT_EQ(r.byte_offset, 80u);
  // A binary STL with a NaN corner.
  Bytes n;
  n.s.assign(80, ' ');
  n.put<std::uint32_t>(1);
  for (int i = 0; i < 12; ++i) n.put(i == 7 ? std::numeric_limits<float>::quiet_NaN() : 0.f);
  n.put<std::uint16_t>(0);
  const auto rn = parse<T>(n.s, MeshFormat::stl);
  EXPECT_EQ(rn.status, Status::non_finite_input);
  EXPECT_EQ(rn.byte_offset, 84u + 28u);
}

// Every prefix and many random byte edits of valid files, in every format: the readers return
// ok or an error status, never crash; a binary prefix is always an error.
TYPED_TEST(MeshIoTest, TruncatedAndCorruptedFilesNeverCrash) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const PolygonMesh<T> m = random_mesh<T>(rng, 12, 6);
  for (const MeshFormat f :
       {MeshFormat::obj, MeshFormat::off, MeshFormat::ply_ascii, MeshFormat::ply_binary_le,
        MeshFormat::ply_binary_be, MeshFormat::stl_ascii, MeshFormat::stl_binary}) {
    SCOPED_TRACE(static_cast<int>(f));
    PolygonMesh<T> src = m;
    if (f == MeshFormat::stl_binary) {
      for (auto& v : src.vertices) {
        for (int k = 0; k < 3; ++k) v[k] = T(float(std::fmod(v[k], T(1e6))));
      }
    }
    const std::string file = locus::write_mesh_string(src, f).data;
    ASSERT_FALSE(file.empty());
    const bool binary = f == MeshFormat::ply_binary_le || f == MeshFormat::ply_binary_be ||
                        f == MeshFormat::stl_binary;
    for (std::size_t n = 0; n < file.size(); ++n) {
      const auto r = parse<T>(std::string_view(file).substr(0, n), f);
      if (binary) {
        ASSERT_EQ(r.status, Status::parse_error) << n;
      }
      if (r.status != Status::ok) {
        ASSERT_FALSE(r.message.empty());
      }
    }
    for (int k = 0; k < 2000; ++k) {
      std::string g = file;
      const int edits = rng.uniform_int(1, 4);
      for (int e = 0; e < edits; ++e) {
        g[std::size_t(rng.uniform_int(0, int(g.size()) - 1))] =
            static_cast<char>(rng.uniform_int(0, 255));
      }
      const auto r = parse<T>(g, f);
      if (r.status == Status::ok) {
        ASSERT_EQ(locus::check_polygon_mesh(r.mesh), Status::ok);
      } else {
        ASSERT_FALSE(r.message.empty());
      }
    }
  }
}

}  // namespace
