// The readers on small files written here and on the broken-file corpus (data/bad), whose
// manifest expected.tsv says which error class, line and phrase each file must produce.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "test_support.hpp"
#include "vorocrust/error.hpp"
#include "vorocrust/read_mesh.hpp"

namespace vorocrust {
namespace {

std::filesystem::path write_text(const test::TempDir& dir, const std::string& name, const std::string& text) {
  const auto path = dir / name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

struct BadFile {
  std::string file, kind;
  int exit_code;
  std::size_t line;
  std::string phrase;
};

std::ostream& operator<<(std::ostream& os, const BadFile& b) { return os << b.file; }

std::vector<BadFile> load_manifest() {
  std::vector<BadFile> rows;
  std::ifstream in(test::data("bad/expected.tsv"));
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream fields(line);
    BadFile b;
    std::string exit_code, line_no;
    std::getline(fields, b.file, '\t');
    std::getline(fields, b.kind, '\t');
    std::getline(fields, exit_code, '\t');
    std::getline(fields, line_no, '\t');
    std::getline(fields, b.phrase, '\t');
    b.exit_code = std::stoi(exit_code);
    b.line = std::stoul(line_no);
    rows.push_back(b);
  }
  return rows;
}

class BrokenFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(BrokenFile, RaisesItsSpecificError) {
  const BadFile& b = GetParam();
  const auto path = test::data("bad/" + b.file);
  try {
    (void)read_mesh(path);
    FAIL() << b.file << " was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(to_string(e.kind())), b.kind) << e.what();
    EXPECT_NE(e.message().find(b.phrase), std::string::npos) << "message: " << e.what();
    EXPECT_EQ(e.where().file, path.string());
    EXPECT_EQ(e.where().line, b.line) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, BrokenFile, ::testing::ValuesIn(load_manifest()),
                         [](const ::testing::TestParamInfo<BadFile>& info) {
                           std::string name = info.param.file;
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

TEST(BrokenFileCorpus, ManifestListsEveryFile) {
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::data("bad"))) {
    files += entry.path().filename() != "expected.tsv";
  }
  EXPECT_EQ(load_manifest().size(), files);
  EXPECT_GE(files, 30u);
}

TEST(ReadMesh, MissingFileAndDirectoryAreUnreadable) {
  test::TempDir dir("readers");
  try {
    (void)read_mesh(dir / "absent.obj");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::UnreadableInput);
    EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos);
  }
  std::filesystem::create_directory(dir / "folder.off");
  try {
    (void)read_mesh(dir / "folder.off");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos);
  }
}

TEST(ReadObj, GroupsFacesPolygonsAndRelativeIndices) {
  test::TempDir dir("readers");
  const auto path = write_text(dir, "quad.obj",
                               "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
                               "f 1/1/1 2/2/2 3/3/3 4/4/4\n"  // a quad before any group: two triangles
                               "g lid\nf -5 -1 -4\n"           // relative indices
                               "o other\nf 1//1 5//1 4//1\n"
                               "g lid\nf 2 3 5\n");            // a name used again continues its group
  const SurfaceMesh m = read_mesh(path);
  ASSERT_EQ(m.num_faces(), 5u);
  ASSERT_EQ(m.groups.size(), 3u);
  EXPECT_EQ(m.groups[0].name, "quad");
  EXPECT_EQ(m.groups[1].name, "lid");
  EXPECT_EQ(m.groups[2].name, "other");
  EXPECT_EQ(m.face_group, (std::vector<Index>{0, 0, 1, 2, 1}));
  EXPECT_EQ(m.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(m.triangles[1], (Triangle{0, 2, 3}));
  EXPECT_EQ(m.triangles[2], (Triangle{0, 4, 1}));
  EXPECT_EQ(m.face_line, (std::vector<std::uint32_t>{6, 6, 8, 10, 12}));
  EXPECT_FALSE(m.has_regions());
}

TEST(ReadObj, GroupsNamedWithARegionPairLabelFaces) {
  test::TempDir dir("readers");
  const auto path = write_text(dir, "two.obj",
                               "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                               "g BRAIN|SKULL\nf 1 2 3\ng SKULL|AIR\nf 1 2 4\ng plain\nf 2 3 4\n");
  const SurfaceMesh m = read_mesh(path);
  ASSERT_TRUE(m.has_regions());
  EXPECT_EQ(m.region_names, (std::vector<std::string>{"BRAIN", "SKULL", "AIR"}));
  EXPECT_EQ(m.face_regions[0], (RegionPair{0, 1}));
  EXPECT_EQ(m.face_regions[1], (RegionPair{1, 2}));
  EXPECT_EQ(m.face_regions[2], RegionPair{});
}

TEST(ReadStl, AsciiWeldsEqualCornersWithoutMovingThem) {
  test::TempDir dir("readers");
  const auto path = write_text(dir, "two.stl",
                               "solid pair\n"
                               " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"
                               "  endloop\n endfacet\n"
                               " facet normal 0 0 1\n  outer loop\n   vertex 1 0 0\n   vertex 1 1 0\n   vertex 0 1 0\n"
                               "  endloop\n endfacet\n"
                               " facet normal 0 0 1\n  outer loop\n   vertex -0 0 0\n   vertex 0.1 0 -1\n   vertex 0 1 0\n"
                               "  endloop\n endfacet\n"
                               "endsolid pair\n");
  const SurfaceMesh m = read_mesh(path);
  EXPECT_EQ(m.num_faces(), 3u);
  EXPECT_EQ(m.num_vertices(), 5u);  // -0 and 0 are one vertex
  EXPECT_EQ(m.groups.at(0).name, "pair");
  EXPECT_EQ(m.vertices[4], Point(0.1, 0, -1));  // kept exactly as read (no rounding to float)
  EXPECT_EQ(m.face_line, (std::vector<std::uint32_t>{2, 9, 16}));
}

TEST(ReadStl, BinaryThatStartsWithSolidIsReadAsBinary) {
  test::TempDir dir("readers");
  std::string bytes(80, '\0');
  bytes.replace(0, 11, "solid trick");
  const std::uint32_t n = 2;
  bytes.append(reinterpret_cast<const char*>(&n), 4);
  const float tris[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 0}};
  for (const auto& t : tris) {
    bytes.append(reinterpret_cast<const char*>(t), sizeof t);
    bytes.append(2, '\0');
  }
  const SurfaceMesh m = read_mesh(write_text(dir, "trick.stl", bytes));
  EXPECT_EQ(m.num_faces(), 2u);
  EXPECT_EQ(m.num_vertices(), 4u);
}

TEST(ReadPly, AsciiAndBinaryWithRegionsAndExtraProperties) {
  test::TempDir dir("readers");
  const std::string header =
      "ply\nformat ascii 1.0\ncomment vorocrust region 0 inside\ncomment vorocrust region 1 outside\n"
      "element vertex 4\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty int back_region\nproperty int front_region\n"
      "element extra 1\nproperty list int int junk\nend_header\n";
  const SurfaceMesh m = read_mesh(write_text(dir, "quad.ply", header + "0 0 0 1\n1 0 0 2\n1 1 0 3\n0 1 0 4\n4 0 1 2 3 0 1\n2 7 7\n"));
  ASSERT_EQ(m.num_faces(), 2u);
  EXPECT_EQ(m.vertices[2], Point(1, 1, 0));
  ASSERT_TRUE(m.has_regions());
  EXPECT_EQ(m.region_names, (std::vector<std::string>{"inside", "outside"}));
  EXPECT_EQ(m.face_regions[1], (RegionPair{0, 1}));
  EXPECT_EQ(m.face_line[0], 21u);

  std::string big = "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                    "property float z\nelement face 1\nproperty list uchar ushort vertex_indices\nend_header\n";
  const auto be_float = [&](float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    for (int s = 24; s >= 0; s -= 8) big.push_back(static_cast<char>((u >> s) & 0xff));
  };
  for (float f : {0.f, 0.f, 0.f, 2.f, 0.f, 0.f, 0.f, 3.f, 0.f}) be_float(f);
  big += std::string("\x03\x00\x00\x00\x01\x00\x02", 7);
  const SurfaceMesh b = read_mesh(write_text(dir, "big.ply", big));
  ASSERT_EQ(b.num_faces(), 1u);
  EXPECT_EQ(b.vertices[1], Point(2, 0, 0));
  EXPECT_EQ(b.triangles[0], (Triangle{0, 1, 2}));
}

// Found by fuzzing (tests/fuzz/corpus/ply/element-without-properties.ply): an element with no
// property takes no byte per record, so its count bounds nothing; 4e18 of them are skipped, not
// counted through. An element with properties may not promise more records than the file holds.
TEST(ReadPly, ElementCountsBoundedByTheFile) {
  test::TempDir dir("readers");
  const std::string tetra =
      "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const SurfaceMesh m =
      read_mesh(write_text(dir, "empty_element.ply", "ply\nformat ascii 1.0\nelement nothing 4000000000000000000\n" + tetra));
  EXPECT_EQ(m.num_faces(), 1u);
  try {
    read_mesh(write_text(dir, "many.ply", "ply\nformat ascii 1.0\nelement junk 4000000000\nproperty int a\n" + tetra));
    ADD_FAILURE() << "a count beyond the file's size was read";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::UnreadableInput);
    EXPECT_NE(std::string(e.what()).find("more 'junk' elements (4000000000) than the file can hold"), std::string::npos)
        << e.what();
  }
}

// Found by fuzzing (tests/fuzz/corpus/ply/huge-float-index.ply): indices and labels given as
// floats far beyond the integers are refused and named, never cast.
TEST(ReadPly, FloatIndicesAndLabelsBeyondTheIntegers) {
  test::TempDir dir("readers");
  const std::string vertices =
      "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n";
  const auto refusal = [&](const std::string& name, const std::string& text) -> std::string {
    try {
      read_mesh(write_text(dir, name, text));
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::UnreadableInput);
      return e.what();
    }
    return "read";
  };
  EXPECT_NE(refusal("index.ply", "ply\nformat ascii 1.0\n" + vertices +
                                     "element face 1\nproperty list uchar float vertex_indices\nend_header\n"
                                     "0 0 0\n1 0 0\n0 1 0\n3 0 1 3.3e124\n")
                .find("face 0 refers to vertex 3.3e+124 but the file has 3 vertices"),
            std::string::npos);
  EXPECT_NE(refusal("label.ply", "ply\nformat ascii 1.0\n" + vertices +
                                     "element face 1\nproperty list uchar int vertex_indices\nproperty float back_region\n"
                                     "property float front_region\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1e20 0\n")
                .find("face 0 has a region label outside -1..65535"),
            std::string::npos);
}

TEST(ReadOff, HeaderAndCountsOnOneLineAndComments) {
  test::TempDir dir("readers");
  const SurfaceMesh m = read_mesh(write_text(dir, "t.off", "OFF 3 1 0 # counts here\n# a comment\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n"));
  EXPECT_EQ(m.num_faces(), 1u);
  EXPECT_EQ(m.face_line[0], 6u);
}

TEST(ReadMeshes, VerticesSharedAcrossFilesButNotWithinOne) {
  test::TempDir dir("readers");
  const auto a = write_text(dir, "a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\n");
  const auto b = write_text(dir, "b.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 0 1\n3 0 1 2\n");
  const SurfaceMesh m = read_meshes({a, b});
  EXPECT_EQ(m.num_vertices(), 5u);  // a's duplicate stays; b's first two corners are a's
  EXPECT_EQ(m.triangles[2], (Triangle{0, 1, 4}));
  EXPECT_EQ(m.groups[1].source_file, b.string());
  EXPECT_EQ(m.face_line[2], 6u);
}

}  // namespace
}  // namespace vorocrust
