// SPDX-License-Identifier: BSL-1.0
// Tests of io/point_list.hpp. Round trips write -> read compare the points bit for bit over
// awkward values (subnormals, extremes, negative zero); the reader is checked against an
// independent printer and parser (printf "%.*g" with max_digits10, strtod / strtof); every
// syntax variant is read from hand-written text with the values written in it; every malformed
// input gives parse_error on its own line; hostile inputs (a line of 10^6 fields, a long number)
// stay bounded; the committed fuzz inputs keep the fuzz property (tests/fuzz/csv_fuzz.hpp).

#include <locus/io/point_list.hpp>

#include "fuzz/csv_fuzz.hpp"
#include "support/files.hpp"
#include "support/typed.hpp"

#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace {

using locus::PointListFormat;
using locus::Status;

template <class T>
class PointListTest : public ::testing::Test {};
TYPED_TEST_SUITE(PointListTest, locus_test::RealTypes);

template <class T, int N>
bool same_bits(const std::vector<locus::Vec<T, N>>& a, const std::vector<locus::Vec<T, N>>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
}

// Random points with awkward coordinates: specials, every binade, plain decimals.
template <class T, int N>
std::vector<locus::Vec<T, N>> awkward_points(locus_test::Rng& rng, int n) {
  const T specials[] = {T(0),
                        -T(0),
                        std::numeric_limits<T>::denorm_min(),
                        -std::numeric_limits<T>::min(),
                        std::numeric_limits<T>::max(),
                        std::numeric_limits<T>::lowest(),
                        T(0.1),
                        T(1) / T(3)};
  const int max_exp = std::numeric_limits<T>::max_exponent - 1;
  std::vector<locus::Vec<T, N>> pts(static_cast<std::size_t>(n));
  for (auto& p : pts) {
    for (int i = 0; i < N; ++i) {
      const int kind = rng.uniform_int(0, 9);
      if (kind == 0) {
        p[i] = specials[std::size_t(rng.uniform_int(0, 7))];
      } else if (kind <= 3) {
        p[i] = std::ldexp(rng.uniform(T(-1), T(1)), rng.uniform_int(-max_exp, max_exp));
      } else {
        p[i] = rng.uniform(T(-1000), T(1000));
      }
    }
  }
  return pts;
}

template <class T, int N>
void round_trip(locus_test::Rng& rng, PointListFormat format) {
  const auto pts = awkward_points<T, N>(rng, 500);
  const auto w = locus::write_points_string<T, N>(pts, format);
  ASSERT_EQ(w.status, Status::ok) << w.message;
  const auto r = locus::parse_points<T, N>(w.data, format, "round-trip");
  ASSERT_EQ(r.status, Status::ok) << r.message;
  EXPECT_TRUE(same_bits(pts, r.points));
  // The same through files, with the format from the extension.
  const auto path = std::filesystem::temp_directory_path() /
                    ("locus_point_list_" + std::to_string(rng.seed()) + "_" + std::to_string(N) +
                     (format == PointListFormat::xyz ? ".xyz" : ".csv"));
  ASSERT_EQ((locus::write_points<T, N>(path, pts).status), Status::ok);
  const auto f = locus::read_points<T, N>(path);
  std::filesystem::remove(path);
  ASSERT_EQ(f.status, Status::ok) << f.message;
  EXPECT_TRUE(same_bits(pts, f.points));
}

TYPED_TEST(PointListTest, RoundTripIsBitExact) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  round_trip<T, 2>(rng, PointListFormat::csv);
  round_trip<T, 3>(rng, PointListFormat::csv);
  round_trip<T, 3>(rng, PointListFormat::xyz);
}

template <class T>
T strto(const char* s) {
  if constexpr (std::is_same_v<T, float>) {
    return std::strtof(s, nullptr);
  } else {
    return std::strtod(s, nullptr);
  }
}

// An independent printer (printf, max_digits10, mixed separators) and parser (strtod/strtof).
TYPED_TEST(PointListTest, ReadsWhatPrintfPrintsAsStrtodReadsIt) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto pts = awkward_points<T, 3>(rng, 300);
  const int digits = std::numeric_limits<T>::max_digits10;
  const char* const seps[] = {",", " ; ", "\t", "  "};
  for (const char* sep : seps) {
    std::string text = "# printed by printf\r\n";
    std::vector<locus::Vec<T, 3>> expected;
    for (const auto& p : pts) {
      locus::Vec<T, 3> e{};
      for (int i = 0; i < 3; ++i) {
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.*g", digits, double(p[i]));
        e[i] = strto<T>(buf);
        text += buf;
        text += i < 2 ? sep : "\r\n";
      }
      expected.push_back(e);
    }
    const auto r = locus::parse_points<T, 3>(text, PointListFormat::csv);
    ASSERT_EQ(r.status, Status::ok) << r.message;
    EXPECT_TRUE(same_bits(expected, r.points)) << "separator '" << sep << "'";
    EXPECT_TRUE(same_bits(pts, r.points));  // max_digits10 itself round-trips
  }
}

TYPED_TEST(PointListTest, SyntaxVariants) {
  using T = TypeParam;
  using V2 = locus::Vec2<T>;
  using V3 = locus::Vec3<T>;
  const std::vector<V2> two = {V2{T(1.5), T(-2)}, V2{T(0.25), T(3e2)}};
  const char* const csv2[] = {
      "x,y\n1.5,-2\n0.25,3e2\n",
      "x;y\r\n1.5;-2\r\n0.25;300\r\n",
      "  X  Y \n 1.5\t-2\n\n0.25   +300  \n",
      "# comment\n\n\"x\",\"y\"\n\"1.5\",\"-2\" # trailing\n0.25 , 3E+2\n",
      "1.5,-2\n# between\n   \n0.25,300",  // no header, no final newline
  };
  for (const char* text : csv2) {
    SCOPED_TRACE(text);
    const auto r = locus::parse_points<T, 2>(text, PointListFormat::csv);
    ASSERT_EQ(r.status, Status::ok) << r.message;
    EXPECT_TRUE(same_bits(two, r.points));
  }
  const std::vector<V3> three = {V3{T(1), T(2), T(3)}, V3{T(-0.5), T(0), T(7)}};
  const char* const xyz[] = {
      "1 2 3\n-0.5 0 7\n",
      "# x y z r g b\r\n1 2 3 255 0 0\r\n-0.5\t0\t7 nx ny nz anything\r\n",
  };
  for (const char* text : xyz) {
    SCOPED_TRACE(text);
    const auto r = locus::parse_points<T, 3>(text, PointListFormat::xyz);
    ASSERT_EQ(r.status, Status::ok) << r.message;
    EXPECT_TRUE(same_bits(three, r.points));
  }
  // Underflow reads as a zero of the right sign.
  const auto u = locus::parse_points<T, 2>("1e-400,-1e-400\n", PointListFormat::csv);
  ASSERT_EQ(u.status, Status::ok) << u.message;
  EXPECT_FALSE(std::signbit(u.points[0].x));
  EXPECT_TRUE(std::signbit(u.points[0].y));
  EXPECT_EQ(u.points[0].y, T(0));
}

TYPED_TEST(PointListTest, EmptyInputsAreOkWithoutPoints) {
  using T = TypeParam;
  for (const char* text : {"", "\n\n", "# nothing\r\n", "x,y\n", "  \t \n# c\n"}) {
    SCOPED_TRACE(text);
    const auto r = locus::parse_points<T, 2>(text, PointListFormat::csv);
    EXPECT_EQ(r.status, Status::ok) << r.message;
    EXPECT_TRUE(r.points.empty());
  }
}

struct Malformed {
  const char* text;
  PointListFormat format;
  int dimension;
  std::size_t line;
  const char* reason;
};

TYPED_TEST(PointListTest, MalformedInputsReportTheirLine) {
  using T = TypeParam;
  using F = PointListFormat;
  const Malformed cases[] = {
      {"1,2\n3,x\n", F::csv, 2, 2, "bad number 'x' in field 2"},
      {"1,2\n3\n", F::csv, 2, 2, "expected 2 fields, found 1"},
      {"1,2,3\n", F::csv, 2, 1, "expected 2 fields, found 3"},
      {"1,2\n1,2,\n", F::csv, 2, 2, "expected 2 fields, found 3"},
      {"1,2,3\n4,,6\n", F::csv, 3, 2, "empty field 2"},
      {"x,y\n1,2\nfoo,bar\n", F::csv, 2, 3, "bad number 'foo' in field 1"},
      {"nan,1\n", F::csv, 2, 1, "non-finite coordinate 'nan' in field 1"},
      {"0,0\n1,-inf\n", F::csv, 2, 2, "non-finite coordinate '-inf' in field 2"},
      {"1,2\r\n\r\n# c\r\n1e999,0\r\n", F::csv, 2, 4, "non-finite coordinate '1e999'"},
      {"# c\n\n1,2\r\n3;4\n", F::csv, 2, 4, "expected 2 fields, found 1"},
      {"1 2\n3 4\n5 6 7\n", F::csv, 2, 3, "expected 2 fields, found 3"},
      {"1,2\n3,4\n5,\0\n", F::csv, 2, 3, "NUL byte"},
      {"0x1p3,2\n", F::csv, 2, 1, "bad number '0x1p3'"},
      {"1,2\n1.5.2,3\n", F::csv, 2, 2, "bad number '1.5.2'"},
      {"1 2 3\n4 5\n", F::xyz, 3, 2, "expected 3 columns (x y z), found 2"},
      {"1 2 3\n4 5 z 0\n", F::xyz, 3, 2, "bad number 'z' in field 3"},
      {"# h\n1 2 NaN\n", F::xyz, 3, 2, "non-finite coordinate 'NaN'"},
      {"x y z\n1 2 3\n", F::xyz, 3, 1, "bad number 'x'"},  // XYZ has no header
  };
  for (const Malformed& c : cases) {
    // The NUL case needs its true length.
    const std::string text = std::string(c.text) == "1,2\n3,4\n5,"
                                 ? std::string("1,2\n3,4\n5,\0\n", 12)
                                 : std::string(c.text);
    SCOPED_TRACE(text);
    Status s;
    std::size_t line;
    std::string message;
    if (c.dimension == 2) {
      const auto r = locus::parse_points<T, 2>(text, c.format, "in.csv");
      s = r.status, line = r.line, message = r.message;
      EXPECT_TRUE(r.points.empty());
    } else {
      const auto r = locus::parse_points<T, 3>(text, c.format, "in.csv");
      s = r.status, line = r.line, message = r.message;
    }
    EXPECT_EQ(s, Status::parse_error);
    EXPECT_EQ(line, c.line);
    const std::string prefix = "in.csv:" + std::to_string(c.line) + ": ";
    EXPECT_EQ(message.rfind(prefix, 0), 0u) << message;
    EXPECT_NE(message.find(c.reason), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
  }
}

TYPED_TEST(PointListTest, HostileInputsStayBounded) {
  using T = TypeParam;
  // A line of a million fields: counted, never stored.
  std::string wide(1000000, ',');
  wide = "1,2\n" + wide + "\n";
  const auto r = locus::parse_points<T, 2>(wide, PointListFormat::csv, "wide");
  EXPECT_EQ(r.status, Status::parse_error);
  EXPECT_EQ(r.line, 2u);
  EXPECT_NE(r.message.find("found 1000001"), std::string::npos) << r.message;
  // A 100000-digit number rounds correctly (to the overflow it is).
  const std::string big = "1" + std::string(100000, '0') + ",0\n";
  const auto b = locus::parse_points<T, 2>(big, PointListFormat::csv, "big");
  EXPECT_EQ(b.status, Status::parse_error);
  EXPECT_NE(b.message.find("non-finite"), std::string::npos);
  // Quoted error tokens are shortened in the message.
  const std::string junk = "1," + std::string(5000, 'q') + "\n";
  const auto j = locus::parse_points<T, 2>(junk, PointListFormat::csv, "junk");
  EXPECT_EQ(j.status, Status::parse_error);
  EXPECT_LT(j.message.size(), 200u);
}

TEST(PointList, FormatsDimensionsAndRefusals) {
  EXPECT_EQ(locus::point_list_format_from_name("a/b.CSV"), PointListFormat::csv);
  EXPECT_EQ(locus::point_list_format_from_name("b.tsv"), PointListFormat::csv);
  EXPECT_EQ(locus::point_list_format_from_name("b.txt"), PointListFormat::csv);
  EXPECT_EQ(locus::point_list_format_from_name("cloud.Xyz"), PointListFormat::xyz);
  EXPECT_EQ(locus::point_list_format_from_name("mesh.obj"), PointListFormat::from_extension);
  EXPECT_EQ(locus::point_list_format_from_name("dir.csv/file"), PointListFormat::from_extension);
  EXPECT_EQ(locus::point_list_dimension("x,y,z\n1,2,3\n", PointListFormat::csv), 3);
  EXPECT_EQ(locus::point_list_dimension("# c\n\n1 2\n", PointListFormat::csv), 2);
  EXPECT_EQ(locus::point_list_dimension("x;y\n", PointListFormat::csv), 0);
  EXPECT_EQ(locus::point_list_dimension("1 2 3 4 5\n", PointListFormat::xyz), 3);
  EXPECT_EQ(locus::point_list_dimension("", PointListFormat::xyz), 0);
  // XYZ is 3D only; the unknown format is named.
  const auto x = locus::parse_points<double, 2>("1 2 3\n", PointListFormat::xyz, "c.xyz");
  EXPECT_EQ(x.status, Status::invalid_input);
  const auto u = locus::parse_points<double, 2>("1,2\n", PointListFormat::from_extension, "a.dat");
  EXPECT_EQ(u.status, Status::invalid_input);
  EXPECT_NE(u.message.find("a.dat"), std::string::npos);
  const auto m = locus::read_points<double, 2>("/nonexistent/dir/p.csv");
  EXPECT_EQ(m.status, Status::io_error);
  // Writing refuses non-finite points and 2D XYZ.
  const std::vector<locus::Vec2d> bad = {{1, std::numeric_limits<double>::quiet_NaN()}};
  EXPECT_EQ((locus::write_points_string<double, 2>(bad, PointListFormat::csv).status),
            Status::non_finite_input);
  const std::vector<locus::Vec2d> ok = {{1, 2}};
  EXPECT_EQ((locus::write_points_string<double, 2>(ok, PointListFormat::xyz).status),
            Status::invalid_input);
  EXPECT_EQ((locus::write_points_string<double, 2>(ok, PointListFormat::csv).data), "x,y\n1,2\n");
}

TEST(PointList, WritesAnyPointRangeWithoutTemplateArguments) {
  const std::vector<locus::Vec2f> v = {{1.5f, -2.0f}, {0.0f, 3.0f}};
  const std::array<locus::Vec3d, 2> a = {locus::Vec3d{1, 2, 3}, locus::Vec3d{-0.0, 0.5, 7}};
  const auto wv = locus::write_points_string(v, PointListFormat::csv);
  ASSERT_EQ(wv.status, Status::ok);
  const auto rv = locus::parse_points<float, 2>(wv.data, PointListFormat::csv);
  ASSERT_EQ(rv.status, Status::ok);
  EXPECT_TRUE(same_bits(std::vector<locus::Vec2f>(v), rv.points));
  const auto path = std::filesystem::temp_directory_path() /
                    ("locus_point_list_range_" + std::to_string(::getpid()) + ".xyz");
  ASSERT_EQ(locus::write_points(path, a).status, Status::ok);
  const auto ra = locus::read_points<double, 3>(path);
  std::filesystem::remove(path);
  ASSERT_EQ(ra.status, Status::ok) << ra.message;
  EXPECT_TRUE(same_bits(std::vector<locus::Vec3d>(a.begin(), a.end()), ra.points));
}

using locus_test::slurp;

TEST(PointListFuzzCorpus, EveryCommittedInputKeepsTheReaderProperty) {
  const std::filesystem::path root = std::filesystem::path(LOCUS_SOURCE_DIR) / "tests" / "fuzz";
  int seeds = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const auto dir = root / kind / "csv";
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      SCOPED_TRACE(entry.path().string());
      const std::string bytes = slurp(entry.path());
      EXPECT_EQ(locus_fuzz::check_point_lists(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                              bytes.size()),
                "");
      if (std::string(kind) == "corpus") {
        ++seeds;
        // Every seed is a valid file of its own kind and dimension.
        const auto f = locus::point_list_format_from_name(entry.path().string());
        const int d = locus::point_list_dimension(bytes, f);
        if (d == 2) {
          const auto r = locus::parse_points<double, 2>(bytes, f);
          EXPECT_EQ(r.status, Status::ok) << r.message;
          EXPECT_FALSE(r.points.empty());
        } else {
          const auto r = locus::parse_points<double, 3>(bytes, f);
          EXPECT_EQ(r.status, Status::ok) << r.message;
          EXPECT_FALSE(r.points.empty());
        }
      }
    }
  }
  EXPECT_GE(seeds, 5);
}

}  // namespace

namespace {

// Rows of six fields (ray files of `locus raycast`: origin and direction): read only. The
// values come from an independent printer and parser; a fifth or seventh field, or a bad
// number, is parse_error on its own line.
TYPED_TEST(PointListTest, SixColumnRowsReadAsPrintfPrintsThem) {
  using T = TypeParam;
  locus_test::Rng rng;
  SCOPED_TRACE(rng.trace());
  const auto pts = awkward_points<T, 6>(rng, 200);
  const int digits = std::numeric_limits<T>::max_digits10;
  std::string text = "ox,oy,oz,dx,dy,dz\n";
  std::vector<locus::Vec<T, 6>> expected;
  for (const auto& p : pts) {
    locus::Vec<T, 6> e{};
    for (int i = 0; i < 6; ++i) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.*g", digits, double(p[i]));
      e[i] = strto<T>(buf);
      text += buf;
      text += i < 5 ? "," : "\n";
    }
    expected.push_back(e);
  }
  const auto r = locus::parse_points<T, 6>(text, PointListFormat::csv);
  ASSERT_EQ(r.status, Status::ok) << r.message;
  EXPECT_TRUE(same_bits(expected, r.points));

  const char* const bad[] = {"1,2,3,4,5,6\n1,2,3,4,5\n", "1,2,3,4,5,6\n1,2,3,4,5,6,7\n",
                             "1,2,3,4,5,6\n1,2,3,4,x,6\n", "1,2,3,4,5,6\n1,2,3,4,5,nan\n"};
  for (const char* b : bad) {
    const auto e = locus::parse_points<T, 6>(b, PointListFormat::csv);
    EXPECT_EQ(e.status, Status::parse_error) << b;
    EXPECT_EQ(e.line, 2u) << b << ": " << e.message;
  }
}

}  // namespace
