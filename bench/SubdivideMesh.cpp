// ptview_subdivide: makes a dense triangle mesh for benchmarks out of a small one.
//
//   ptview_subdivide IN.obj OUT.obj [--levels N]      (N defaults to 1)
//
// Each level splits every triangle into four at its edge midpoints (no smoothing, so the shape is
// unchanged and the triangle count grows by 4^N). A midpoint is made once per edge and shared by
// the triangles on both sides, so a closed input stays closed: V' = V + E, F' = 4F.
//
// Input: `v x y z` and `f` records only; face corners may be `a`, `a/b`, `a//c` or `a/b/c`, with
// negative (relative) indices, and polygons are split into fans. Every other record (`vn`, `vt`,
// `l`, `g`, `s`, comments, ...) is ignored. Output: positions and triangles only, no normals,
// written to OUT.tmp and then renamed, so a reader never sees half a file.
//
// Standard library only: this is a build-time tool and needs none of the renderer.

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace {

struct Vec3 {
  float x, y, z;
};

struct Mesh {
  std::vector<Vec3> positions;
  std::vector<uint32_t> indices;  // three per triangle, zero-based
};

constexpr int kMaxLevels = 8;
// Indices are 32-bit; refuse before the counts wrap rather than write a corrupt file.
constexpr uint64_t kMaxTriangles = uint64_t(1) << 31;

[[noreturn]] void fail(const std::string& message) { throw std::runtime_error(message); }

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path + ": cannot open for reading");
  std::ostringstream contents;
  contents << in.rdbuf();
  if (in.bad()) fail(path + ": read error");
  return std::move(contents).str();
}

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view nextToken(std::string_view& line) {
  size_t begin = 0;
  while (begin < line.size() && isBlank(line[begin])) ++begin;
  size_t end = begin;
  while (end < line.size() && !isBlank(line[end])) ++end;
  std::string_view token = line.substr(begin, end - begin);
  line.remove_prefix(end);
  return token;
}

Mesh parseObj(const std::string& path, const std::string& text) {
  Mesh mesh;
  std::vector<uint32_t> corners;
  size_t lineNumber = 0;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++lineNumber;
    auto where = [&] { return path + ":" + std::to_string(lineNumber) + ": "; };

    std::string_view keyword = nextToken(line);
    if (keyword == "v") {
      float xyz[3];
      for (float& value : xyz) {
        std::string_view token = nextToken(line);
        auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (token.empty() || ec != std::errc() || ptr != token.data() + token.size())
          fail(where() + "bad vertex position '" + std::string(token) + "'");
      }
      mesh.positions.push_back({xyz[0], xyz[1], xyz[2]});  // an optional w (or colour) is dropped
    } else if (keyword == "f") {
      corners.clear();
      for (std::string_view token = nextToken(line); !token.empty(); token = nextToken(line)) {
        std::string_view position = token.substr(0, token.find('/'));  // v of v/vt/vn
        long long index = 0;
        auto [ptr, ec] = std::from_chars(position.data(), position.data() + position.size(), index);
        if (position.empty() || ec != std::errc() || ptr != position.data() + position.size() ||
            index == 0)
          fail(where() + "bad face corner '" + std::string(token) + "'");
        // OBJ counts from 1; a negative index counts back from the last vertex read so far.
        long long count = static_cast<long long>(mesh.positions.size());
        long long zeroBased = index > 0 ? index - 1 : count + index;
        if (zeroBased < 0 || zeroBased >= count)
          fail(where() + "face corner '" + std::string(token) + "' refers to a missing vertex");
        corners.push_back(static_cast<uint32_t>(zeroBased));
      }
      if (corners.size() < 3) fail(where() + "face with fewer than three corners");
      for (size_t k = 1; k + 1 < corners.size(); ++k)
        mesh.indices.insert(mesh.indices.end(), {corners[0], corners[k], corners[k + 1]});
    }
  }
  return mesh;
}

// One level of midpoint subdivision. The edge map keys an undirected edge by its two vertex
// indices (smaller first) so both triangles beside it find the same midpoint vertex.
Mesh subdivideOnce(const Mesh& in) {
  const size_t triangleCount = in.indices.size() / 3;
  Mesh out;
  out.positions = in.positions;
  // A closed mesh has E = 3F/2; the reserve saves rehashing and growing for the common case.
  out.positions.reserve(in.positions.size() + triangleCount * 3 / 2 + 1);
  out.indices.reserve(in.indices.size() * 4);

  std::unordered_map<uint64_t, uint32_t> midpointOfEdge;
  midpointOfEdge.reserve(triangleCount * 3 / 2 + 1);
  auto midpoint = [&](uint32_t a, uint32_t b) {
    uint64_t key = a < b ? (uint64_t(a) << 32 | b) : (uint64_t(b) << 32 | a);
    auto [it, inserted] = midpointOfEdge.try_emplace(key, uint32_t(out.positions.size()));
    if (inserted) {
      const Vec3& p = in.positions[a];
      const Vec3& q = in.positions[b];
      out.positions.push_back({0.5f * (p.x + q.x), 0.5f * (p.y + q.y), 0.5f * (p.z + q.z)});
    }
    return it->second;
  };

  for (size_t t = 0; t < triangleCount; ++t) {
    uint32_t a = in.indices[3 * t], b = in.indices[3 * t + 1], c = in.indices[3 * t + 2];
    uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    // Same winding as the parent, so outward normals stay outward.
    out.indices.insert(out.indices.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
  }
  return out;
}

// Formats the whole file into one buffer: one write instead of millions of small ones.
std::string formatObj(const Mesh& mesh, int levels, const std::string& source) {
  std::string text;
  text.reserve(mesh.positions.size() * 40 + mesh.indices.size() / 3 * 30 + 256);
  text += "# ptview_subdivide: " + source + ", " + std::to_string(levels) +
          " level(s) of midpoint subdivision\n";

  char line[128];
  auto append = [&](char* end) { text.append(line, end); };
  for (const Vec3& p : mesh.positions) {
    char* out = line;
    *out++ = 'v';
    for (float value : {p.x, p.y, p.z}) {
      *out++ = ' ';
      out = std::to_chars(out, line + sizeof(line), value).ptr;  // shortest exact round-trip
    }
    *out++ = '\n';
    append(out);
  }
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    char* out = line;
    *out++ = 'f';
    for (size_t k = 0; k < 3; ++k) {
      *out++ = ' ';
      out = std::to_chars(out, line + sizeof(line), mesh.indices[i + k] + 1ull).ptr;
    }
    *out++ = '\n';
    append(out);
  }
  return text;
}

void writeFileAtomically(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) fail(temporary + ": cannot open for writing: " + std::strerror(errno));
  bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  written = (std::fclose(file) == 0) && written;
  if (!written) {
    std::remove(temporary.c_str());
    fail(temporary + ": write failed (disk full?)");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    fail(path + ": cannot rename " + temporary + " onto it: " + reason);
  }
}

int usage(const char* program) {
  std::fprintf(stderr,
               "usage: %s IN.obj OUT.obj [--levels N]\n"
               "Splits every triangle of IN.obj into 4^N (N = 0..%d, default 1) by edge midpoints,"
               "\nsharing midpoints between neighbours so a closed mesh stays closed.\n",
               program, kMaxLevels);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> paths;
  int levels = 1;
  for (int i = 1; i < argc; ++i) {
    std::string_view arg = argv[i];
    if (arg == "--levels" && i + 1 < argc) {
      std::string_view value = argv[++i];
      auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), levels);
      if (ec != std::errc() || ptr != value.data() + value.size() || levels < 0 ||
          levels > kMaxLevels)
        return usage(argv[0]);
    } else if (arg == "-h" || arg == "--help" || arg.substr(0, 1) == "-") {
      return usage(argv[0]);
    } else {
      paths.emplace_back(arg);
    }
  }
  if (paths.size() != 2) return usage(argv[0]);
  const std::string& inPath = paths[0];
  const std::string& outPath = paths[1];

  try {
    auto start = std::chrono::steady_clock::now();
    Mesh mesh = parseObj(inPath, readFile(inPath));
    if (mesh.indices.empty()) fail(inPath + ": no faces");
    if ((mesh.indices.size() / 3) << (2 * levels) > kMaxTriangles)
      fail(inPath + ": " + std::to_string(levels) + " levels would exceed " +
           std::to_string(kMaxTriangles) + " triangles");
    for (int level = 0; level < levels; ++level) mesh = subdivideOnce(mesh);
    writeFileAtomically(outPath, formatObj(mesh, levels, inPath));
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("wrote %s (%zu vertices, %zu triangles) in %.2f s\n", outPath.c_str(),
                mesh.positions.size(), mesh.indices.size() / 3, seconds);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "ptview_subdivide: %s\n", error.what());
    return 1;
  }
  return 0;
}
