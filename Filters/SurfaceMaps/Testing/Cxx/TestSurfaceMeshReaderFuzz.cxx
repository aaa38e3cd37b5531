// Deterministic mutation fuzzing of every mesh reader and the landmark
// readers (indices and points: .pinned, .vts, .csv, .fcsv, .mrk.json), in process (one process would cost a VTK start-up per input).
//
// Seeds are the files in Data/ plus encodings derived from them here (binary
// PLY in both byte orders, binary STL, VTP ascii / appended raw / zlib,
// legacy VTK 5.1 ascii and binary, OBJ with texture coordinates), so the
// test needs nothing outside the repository. Every seed must read as a
// valid mesh; every mutant (truncation, byte flips, number and index edits
// with huge, negative, 64-bit and non-finite values, deleted, repeated and
// inserted bytes or lines) must either read and validate, or be rejected
// with a message: a reader error naming the file, or the validator's
// defects. A crash, a sanitizer report or an input that takes longer than
// the time bound fails the test.
//
// usage: SurfaceMapsReaderFuzz DATA_DIR SCRATCH_DIR [--mutants N] [--seed S]
//                              [--seconds T] [--emit DIR --every K]
//   --mutants N   mutants per seed file (default 250: 21 seeds, 5 271 inputs)
//   --seconds T   bound on the time of one input (default 20)
//   --verbose 1   name every input before reading it (to find a crash)
//   --only EXT    only the seeds whose name ends with EXT (e.g. .vtp); the
//                 mutants of the others are skipped, the sequence unchanged
//   --emit DIR    also write every K-th mutant to DIR, for the command-line
//                 sample (Testing/Python/test_cli_fuzz.py); landmark mutants
//                 are written as <k>_lm.<ext> beside their mesh <k>_lm_mesh.<ext>
#include "vtkSurfaceMeshReader.h"
#include "vtkSurfaceMeshValidator.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataWriter.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkVariant.h"
#include "vtkXMLPolyDataWriter.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
// Memory as on a small machine: a request above 512 MB fails (no valid seed
// needs more than a few MB) the way a failed allocation fails in a normal
// build, so the path that reports it (the reader's "not enough memory to
// read it", naming the file) runs under the sanitizers too. VTK's XML
// reader sizes cell arrays by the values of a file's offsets array, which
// no check before it can see inside compressed data.
extern "C" const char* __asan_default_options()
{
  return "max_allocation_size_mb=512:allocator_may_return_null=1";
}
#endif

namespace
{

// splitmix64: the same sequence on every platform and standard library
// (std::uniform_int_distribution is not specified bit for bit).
class Random
{
public:
  explicit Random(std::uint64_t seed)
    : State(seed)
  {
  }
  std::uint64_t next()
  {
    std::uint64_t z = (this->State += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, n); n > 0.
  std::size_t below(std::size_t n) { return static_cast<std::size_t>(this->next() % n); }

private:
  std::uint64_t State;
};

// Replacement numbers for counts and indices: the edges of 32- and 64-bit
// ranges, negatives, non-integers and non-finite values.
const char* const InterestingNumbers[] = { "0", "1", "2", "3", "-1", "-2", "255", "256", "65535",
  "65536", "2147483647", "2147483648", "-2147483648", "4294967295", "4294967296", "4294967299",
  "4294967310", "1000000000000", "9223372036854775807", "18446744073709551615",
  "99999999999999999999999", "1e308", "-1e308", "1e-320", "nan", "inf", "-inf", "0.5", "3.0" };

const std::uint32_t InterestingWords[] = { 0u, 1u, 3u, 0xFFu, 0x100u, 0xFFFFu, 0x10000u,
  0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu, 0x01000000u, 0x00FFFFFFu };

using Bytes = std::string;

bool isDigit(char c)
{
  return c >= '0' && c <= '9';
}

// [begin, end) of every maximal run of digits, with a leading '-'.
std::vector<std::pair<std::size_t, std::size_t>> digitRuns(const Bytes& b)
{
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (std::size_t i = 0; i < b.size();)
  {
    if (!isDigit(b[i]))
    {
      ++i;
      continue;
    }
    std::size_t begin = (i > 0 && b[i - 1] == '-') ? i - 1 : i;
    std::size_t end = i;
    while (end < b.size() && isDigit(b[end]))
    {
      ++end;
    }
    runs.emplace_back(begin, end);
    i = end;
  }
  return runs;
}

// [begin, end) of every line.
std::vector<std::pair<std::size_t, std::size_t>> lines(const Bytes& b)
{
  std::vector<std::pair<std::size_t, std::size_t>> result;
  std::size_t begin = 0;
  while (begin < b.size())
  {
    std::size_t end = b.find('\n', begin);
    end = end == Bytes::npos ? b.size() : end + 1;
    result.emplace_back(begin, end);
    begin = end;
  }
  return result;
}

// Lines that hold connectivity in the text formats: integers only (OFF, PLY,
// legacy VTK, VTP ascii), or an OBJ face "f ...".
std::vector<std::pair<std::size_t, std::size_t>> indexLines(const Bytes& b)
{
  std::vector<std::pair<std::size_t, std::size_t>> result;
  for (const auto& line : lines(b))
  {
    const std::string text = b.substr(line.first, line.second - line.first);
    if (text.rfind("f ", 0) == 0)
    {
      result.push_back(line);
      continue;
    }
    bool integers = text.find_first_of("0123456789") != std::string::npos;
    for (char c : text)
    {
      if (!(isDigit(c) || c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '-'))
      {
        integers = false;
        break;
      }
    }
    if (integers)
    {
      result.push_back(line);
    }
  }
  return result;
}

Bytes replaceRange(const Bytes& b, std::size_t begin, std::size_t end, const std::string& with)
{
  return b.substr(0, begin) + with + b.substr(end);
}

// One mutation of `b`; `what` says which, for the failure message.
Bytes mutate(const Bytes& b, Random& random, std::string& what)
{
  const std::size_t n = b.size();
  switch (random.below(9))
  {
    case 0:
    {
      const std::size_t keep = random.below(n);
      what = "truncated to " + std::to_string(keep) + " bytes";
      return b.substr(0, keep);
    }
    case 1:
    {
      Bytes m = b;
      const std::size_t flips = 1 + random.below(8);
      what = std::to_string(flips) + " bytes flipped at";
      for (std::size_t k = 0; k < flips; ++k)
      {
        const std::size_t at = random.below(n);
        m[at] = static_cast<char>(random.next() & 0xFF);
        what += " " + std::to_string(at);
      }
      return m;
    }
    case 2:
    case 3:
    {
      const auto runs = digitRuns(b);
      if (runs.empty())
      {
        break;
      }
      // Counts sit near the start of every format: favour the first runs.
      const std::size_t pick =
        random.below(2) ? random.below(std::min<std::size_t>(runs.size(), 16)) : random.below(runs.size());
      const char* number =
        InterestingNumbers[random.below(sizeof InterestingNumbers / sizeof *InterestingNumbers)];
      what = "number at byte " + std::to_string(runs[pick].first) + " -> " + number;
      return replaceRange(b, runs[pick].first, runs[pick].second, number);
    }
    case 4:
    {
      const auto candidates = indexLines(b);
      if (candidates.empty())
      {
        break;
      }
      const auto line = candidates[random.below(candidates.size())];
      Bytes text = b.substr(line.first, line.second - line.first);
      const auto runs = digitRuns(text);
      if (runs.empty())
      {
        break;
      }
      const auto run = runs[random.below(runs.size())];
      const char* number =
        InterestingNumbers[random.below(sizeof InterestingNumbers / sizeof *InterestingNumbers)];
      text = replaceRange(text, run.first, run.second, number);
      what = "index edit in the line at byte " + std::to_string(line.first) + " -> " + number;
      return replaceRange(b, line.first, line.second, text);
    }
    case 5:
    {
      if (n < 4)
      {
        break;
      }
      Bytes m = b;
      const std::size_t at = random.below(n - 3);
      std::uint32_t word =
        InterestingWords[random.below(sizeof InterestingWords / sizeof *InterestingWords)];
      if (random.below(2))
      {
        word = __builtin_bswap32(word);
      }
      std::memcpy(&m[at], &word, 4);
      what = "32-bit word " + std::to_string(word) + " at byte " + std::to_string(at);
      return m;
    }
    case 6:
    {
      const std::size_t at = random.below(n);
      const std::size_t length = 1 + random.below(64);
      what = "deleted " + std::to_string(length) + " bytes at " + std::to_string(at);
      return b.substr(0, at) + b.substr(std::min(n, at + length));
    }
    case 7:
    {
      const auto all = lines(b);
      const auto line = all[random.below(all.size())];
      const Bytes text = b.substr(line.first, line.second - line.first);
      if (random.below(2))
      {
        what = "line at byte " + std::to_string(line.first) + " deleted";
        return replaceRange(b, line.first, line.second, "");
      }
      what = "line at byte " + std::to_string(line.first) + " repeated";
      return replaceRange(b, line.first, line.first, text);
    }
    default:
    {
      const std::size_t at = random.below(n + 1);
      Bytes inserted(1 + random.below(32), '\0');
      for (char& c : inserted)
      {
        c = static_cast<char>(random.next() & 0xFF);
      }
      what = std::to_string(inserted.size()) + " random bytes inserted at " + std::to_string(at);
      return replaceRange(b, at, at, inserted);
    }
  }
  // The chosen mutation did not apply to this file: flip one byte instead.
  Bytes m = b;
  const std::size_t at = random.below(n);
  m[at] = static_cast<char>(~m[at]);
  what = "byte inverted at " + std::to_string(at);
  return m;
}

Bytes readFile(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (!in)
  {
    std::cerr << "cannot read seed " << path << "\n";
    std::exit(1);
  }
  return buffer.str();
}

void writeFile(const std::string& path, const Bytes& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out)
  {
    std::cerr << "cannot write " << path << "\n";
    std::exit(1);
  }
}

// Triangles of a mesh read by vtkSurfaceMeshReader.
std::vector<std::array<vtkIdType, 3>> triangles(vtkPolyData* mesh)
{
  std::vector<std::array<vtkIdType, 3>> result;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    mesh->GetCellPoints(c, ids);
    result.push_back({ ids->GetId(0), ids->GetId(1), ids->GetId(2) });
  }
  return result;
}

template <typename T>
void put(Bytes& out, T value, bool bigEndian)
{
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (bigEndian)
  {
    std::reverse(raw, raw + sizeof(T));
  }
  out.append(raw, sizeof(T));
}

// Binary PLY: float32 / int32 little endian, or float64 / uint32 big endian.
Bytes binaryPly(vtkPolyData* mesh, bool bigEndian)
{
  const auto tris = triangles(mesh);
  std::ostringstream header;
  header << "ply\nformat " << (bigEndian ? "binary_big_endian" : "binary_little_endian")
         << " 1.0\nelement vertex " << mesh->GetNumberOfPoints() << "\nproperty "
         << (bigEndian ? "double" : "float") << " x\nproperty " << (bigEndian ? "double" : "float")
         << " y\nproperty " << (bigEndian ? "double" : "float") << " z\nelement face "
         << tris.size() << "\nproperty list uchar " << (bigEndian ? "uint" : "int")
         << " vertex_indices\nend_header\n";
  Bytes out = header.str();
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    for (double x : p)
    {
      if (bigEndian)
      {
        put<double>(out, x, true);
      }
      else
      {
        put<float>(out, static_cast<float>(x), false);
      }
    }
  }
  for (const auto& t : tris)
  {
    put<std::uint8_t>(out, 3, bigEndian);
    for (vtkIdType v : t)
    {
      put<std::int32_t>(out, static_cast<std::int32_t>(v), bigEndian);
    }
  }
  return out;
}

// Binary STL: 80-byte header, triangle count, 50 bytes per triangle.
Bytes binaryStl(vtkPolyData* mesh)
{
  const auto tris = triangles(mesh);
  Bytes out(80, ' ');
  out.replace(0, 22, "SurfaceMaps fuzz seed ");
  put<std::uint32_t>(out, static_cast<std::uint32_t>(tris.size()), false);
  for (const auto& t : tris)
  {
    for (int k = 0; k < 3; ++k)
    {
      put<float>(out, 0.0f, false); // normal: recomputed by readers
    }
    for (vtkIdType v : t)
    {
      double p[3];
      mesh->GetPoint(v, p);
      for (double x : p)
      {
        put<float>(out, static_cast<float>(x), false);
      }
    }
    put<std::uint16_t>(out, 0, false);
  }
  return out;
}

// OBJ with a texture coordinate and a normal per corner ("f v/vt/vn").
Bytes objWithCorners(vtkPolyData* mesh)
{
  std::ostringstream out;
  out.precision(17);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    out << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
    out << "vt " << 0.5 + 0.5 * p[0] << " " << 0.5 + 0.5 * p[1] << "\n";
  }
  out << "vn 0 0 1\n";
  for (const auto& t : triangles(mesh))
  {
    out << "f";
    for (vtkIdType v : t)
    {
      out << " " << v + 1 << "/" << v + 1 << "/1";
    }
    out << "\n";
  }
  return out.str();
}

// blob.vts's landmarks ("index x y z" lines) as points, in the formats that
// give landmarks by coordinates: .vts without index, .csv, Slicer .fcsv and
// .mrk.json.
std::vector<std::pair<std::string, Bytes>> landmarkPointSeeds(const Bytes& vts)
{
  std::istringstream in(vts);
  std::ostringstream points, csv, fcsv, json;
  for (std::ostream* out : { static_cast<std::ostream*>(&points), static_cast<std::ostream*>(&csv),
         static_cast<std::ostream*>(&fcsv), static_cast<std::ostream*>(&json) })
  {
    out->precision(17);
  }
  fcsv << "# Markups fiducial file version = 4.11\n# CoordinateSystem = LPS\n"
          "# columns = id,x,y,z,ow,ox,oy,oz,vis,sel,lock,label,desc,associatedNodeID\n";
  json << "{\"markups\": [{\"type\": \"Fiducial\", \"coordinateSystem\": \"LPS\",\n"
          "  \"controlPoints\": [\n";
  int index, k = 0;
  double x, y, z;
  for (; in >> index >> x >> y >> z; ++k)
  {
    points << x << " " << y << " " << z << "\n";
    csv << x << "," << y << "," << z << "," << k << "\n";
    fcsv << "vtkMRMLMarkupsFiducialNode_" << k << "," << x << "," << y << "," << z
         << ",0,0,0,1,1,1,0,F-" << k + 1 << ",,\n";
    json << (k ? ",\n" : "") << "    {\"id\": \"" << k + 1 << "\", \"label\": \"F-" << k + 1
         << "\", \"position\": [" << x << ", " << y << ", " << z
         << "], \"positionStatus\": \"defined\"}";
  }
  json << "\n  ]\n}]}\n";
  return { { "derived_points.vts", points.str() },
    { "derived_points.csv", csv.str() },
    { "derived_points.fcsv", fcsv.str() },
    { "derived_points.mrk.json", json.str() } };
}

// What a VTK writer (legacy or XML) wrote to `path`.
template <typename Writer>
Bytes writtenByVTK(Writer* writer, const std::string& path)
{
  writer->Write();
  return readFile(path);
}

struct Seed
{
  std::string Name;      // extension decides the reader
  Bytes Content;         // what gets mutated
  std::string MeshName;  // landmark seeds: the mesh they belong to
  Bytes MeshContent;
};

struct Tally
{
  long Inputs = 0;
  long Valid = 0;
  long ReaderErrors = 0;
  long InvalidMeshes = 0;
  long Failures = 0;
};

// The input under test and its file, for the time-out handler.
char CurrentInput[512] = "";
char CurrentFile[512] = "";

extern "C" void onTimeout(int)
{
  const char prefix[] = "\nFAIL: time bound exceeded on ";
  const char file[] = "\n  the input is ";
  (void)!write(2, prefix, sizeof prefix - 1);
  (void)!write(2, CurrentInput, std::strlen(CurrentInput));
  (void)!write(2, file, sizeof file - 1);
  (void)!write(2, CurrentFile, std::strlen(CurrentFile));
  (void)!write(2, "\n", 1);
  _exit(1);
}

std::string basename(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Reads `meshPath` (with `landmarkPath`) as `surfacemap check` does and
// classifies the outcome; false on a broken contract.
bool checkOne(const std::string& meshPath, const std::string& landmarkPath, Tally& tally,
  std::string& failure)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  vtkNew<vtkCallbackCommand> sink; // the message is read back below
  reader->AddObserver(vtkCommand::ErrorEvent, sink);
  reader->AddObserver(vtkCommand::WarningEvent, sink); // landmark points far from the mesh
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, sink);
  reader->SetFileName(meshPath.c_str());
  if (!landmarkPath.empty())
  {
    reader->SetLandmarkFileName(landmarkPath.c_str());
  }
  reader->Update();
  const std::string error = reader->GetLastErrorMessage();
  if (!error.empty())
  {
    ++tally.ReaderErrors;
    const std::string named = basename(landmarkPath.empty() ? meshPath : landmarkPath);
    if (error.find(named) == std::string::npos)
    {
      failure = "the reader's message does not name " + named + ": " + error;
      return false;
    }
    return true;
  }
  vtkPolyData* mesh = reader->GetOutput();
  vtkNew<vtkSurfaceMeshValidator> validator;
  validator->AddInputDataObject(mesh);
  validator->Update();
  vtkTable* table = validator->GetOutput();
  if (table->GetNumberOfRows() != 1)
  {
    failure = "the validator gave no verdict";
    return false;
  }
  if (table->GetValueByName(0, "Valid").ToInt())
  {
    ++tally.Valid;
    if (!landmarkPath.empty() && !mesh->GetPointData()->GetArray("Landmarks"))
    {
      failure = "read without error but without its Landmarks array";
      return false;
    }
    return true;
  }
  ++tally.InvalidMeshes;
  if (table->GetValueByName(0, "Defects").ToString().empty())
  {
    failure = "invalid without a defect named";
    return false;
  }
  return true;
}

std::string extensionOf(const std::string& name)
{
  return name.substr(name.find_last_of('.'));
}

std::vector<Seed> makeSeeds(const std::string& data, const std::string& scratch)
{
  std::vector<Seed> seeds;
  auto asIs = [&](const std::string& file)
  { seeds.push_back({ file, readFile(data + "/" + file), "", "" }); };
  asIs("ellipsoid.obj");
  asIs("blob.off");
  asIs("limbs.ply");
  asIs("ellipsoid_coarse.stl");
  asIs("blob.vtp");
  asIs("limbs_coarse.vtk");
  seeds.push_back({ "ellipsoid.pinned", readFile(data + "/ellipsoid.pinned"), "ellipsoid.obj",
    readFile(data + "/ellipsoid.obj") });
  seeds.push_back(
    { "blob.vts", readFile(data + "/blob.vts"), "blob.off", readFile(data + "/blob.off") });

  // Other encodings of blob (642 vertices, with its Landmarks point array).
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName((data + "/blob.vtp").c_str());
  reader->Update();
  vtkPolyData* blob = reader->GetOutput();
  seeds.push_back({ "derived_le.ply", binaryPly(blob, false), "", "" });
  seeds.push_back({ "derived_be.ply", binaryPly(blob, true), "", "" });
  seeds.push_back({ "derived_binary.stl", binaryStl(blob), "", "" });
  seeds.push_back({ "derived_corners.obj", objWithCorners(blob), "", "" });

  const std::string scratchFile = scratch + "/derived_seed";
  struct XmlMode
  {
    const char* Name;
    int DataMode;
    bool Compressed;
    bool Encoded;
  };
  for (const XmlMode& mode : { XmlMode{ "derived_ascii.vtp", vtkXMLWriter::Ascii, false, false },
         XmlMode{ "derived_raw.vtp", vtkXMLWriter::Appended, false, false },
         XmlMode{ "derived_zlib.vtp", vtkXMLWriter::Binary, true, true } })
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(blob);
    writer->SetFileName((scratchFile + ".vtp").c_str());
    writer->SetDataMode(mode.DataMode);
    writer->SetEncodeAppendedData(mode.Encoded);
    if (mode.Compressed)
    {
      writer->SetCompressorTypeToZLib();
    }
    else
    {
      writer->SetCompressorTypeToNone();
    }
    seeds.push_back({ mode.Name, writtenByVTK(writer.GetPointer(), scratchFile + ".vtp"), "", "" });
  }
  for (bool binary : { false, true })
  {
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetInputData(blob);
    writer->SetFileName((scratchFile + ".vtk").c_str());
    writer->SetFileType(binary ? VTK_BINARY : VTK_ASCII);
    seeds.push_back({ binary ? "derived_binary.vtk" : "derived_ascii51.vtk",
      writtenByVTK(writer.GetPointer(), scratchFile + ".vtk"), "", "" });
  }
  std::remove((scratchFile + ".vtp").c_str());
  std::remove((scratchFile + ".vtk").c_str());

  // Landmarks as points (blob.vts's vertices, by coordinates) in every point
  // format; last, so the mutants of the seeds above stay as they were.
  const Bytes blobMesh = readFile(data + "/blob.off");
  for (const auto& [name, content] : landmarkPointSeeds(readFile(data + "/blob.vts")))
  {
    seeds.push_back({ name, content, "blob.off", blobMesh });
  }
  return seeds;
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: SurfaceMapsReaderFuzz DATA_DIR SCRATCH_DIR [--mutants N] [--seed S] "
                 "[--seconds T] [--emit DIR --every K] [--verbose 1]\n";
    return 1;
  }
  const std::string data = argv[1];
  const std::string scratch = argv[2];
  long mutantsPerSeed = 250;
  std::uint64_t seedValue = 20;
  unsigned seconds = 20;
  std::string emitDir;
  long every = 20;
  bool verbose = false;
  std::string only;
  for (int a = 3; a + 1 < argc; a += 2)
  {
    const std::string flag = argv[a];
    if (flag == "--mutants")
      mutantsPerSeed = std::stol(argv[a + 1]);
    else if (flag == "--seed")
      seedValue = std::stoull(argv[a + 1]);
    else if (flag == "--seconds")
      seconds = static_cast<unsigned>(std::stoul(argv[a + 1]));
    else if (flag == "--emit")
      emitDir = argv[a + 1];
    else if (flag == "--every")
      every = std::stol(argv[a + 1]);
    else if (flag == "--verbose")
      verbose = std::stoi(argv[a + 1]) != 0;
    else if (flag == "--only")
      only = argv[a + 1];
    else
    {
      std::cerr << "unknown option " << flag << "\n";
      return 1;
    }
  }
  std::signal(SIGALRM, onTimeout);

  const std::vector<Seed> seeds = makeSeeds(data, scratch);
  Random random(seedValue);
  Tally tally;
  const auto start = std::chrono::steady_clock::now();
  long index = 0;
  for (const Seed& seed : seeds)
  {
    const std::string ext = extensionOf(seed.Name);
    const bool landmarks = !seed.MeshName.empty();
    const std::string meshPath =
      scratch + "/fuzz_mesh" + (landmarks ? extensionOf(seed.MeshName) : ext);
    const std::string landmarkPath = landmarks ? scratch + "/fuzz_landmarks" + ext : "";
    if (landmarks)
    {
      writeFile(meshPath, seed.MeshContent);
    }
    const bool skipped = !only.empty() &&
      (seed.Name.size() < only.size() || seed.Name.compare(seed.Name.size() - only.size(), only.size(), only) != 0);
    for (long m = -1; m < mutantsPerSeed; ++m, ++index)
    {
      std::string what = "unmutated";
      const Bytes content = m < 0 ? seed.Content : mutate(seed.Content, random, what);
      if (skipped)
      {
        continue;
      }
      writeFile(landmarks ? landmarkPath : meshPath, content);
      std::snprintf(
        CurrentInput, sizeof CurrentInput, "%s (%s)", seed.Name.c_str(), what.c_str());
      std::snprintf(CurrentFile, sizeof CurrentFile, "%s",
        (landmarks ? landmarkPath : meshPath).c_str());

      if (verbose)
      {
        std::cerr << "reading " << CurrentInput << "\n";
      }
      alarm(seconds);
      std::string failure;
      const long validBefore = tally.Valid;
      const bool ok = checkOne(meshPath, landmarkPath, tally, failure);
      alarm(0);
      ++tally.Inputs;
      if (m < 0 && tally.Valid == validBefore)
      {
        failure = "the seed itself does not read as a valid mesh" +
          (failure.empty() ? std::string() : ": " + failure);
      }
      if (!ok || !failure.empty())
      {
        ++tally.Failures;
        std::cerr << "FAIL: " << CurrentInput << ": " << failure << "\n";
        const std::string kept = scratch + "/failed_" + std::to_string(index) + "_" +
          basename(landmarks ? landmarkPath : meshPath);
        writeFile(kept, content);
        std::cerr << "  input kept as " << kept << "\n";
      }
      if (!emitDir.empty() && m >= 0 && index % every == 0)
      {
        const std::string stem = emitDir + "/" + std::to_string(index);
        if (landmarks)
        {
          writeFile(stem + "_lm" + ext, content);
          writeFile(stem + "_lm_mesh" + extensionOf(seed.MeshName), seed.MeshContent);
        }
        else
        {
          writeFile(stem + ext, content);
        }
      }
    }
  }
  for (const Seed& seed : seeds)
  {
    std::remove((scratch + "/fuzz_mesh" + extensionOf(seed.Name)).c_str());
    std::remove((scratch + "/fuzz_landmarks" + extensionOf(seed.Name)).c_str());
  }
  const double elapsed =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << tally.Inputs << " inputs from " << seeds.size() << " seeds in " << elapsed
            << " s: " << tally.Valid << " valid, " << tally.ReaderErrors
            << " rejected by the reader, " << tally.InvalidMeshes
            << " read but invalid; " << tally.Failures << " broken contracts" << std::endl;
  return tally.Failures == 0 ? 0 : 1;
}
