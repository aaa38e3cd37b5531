#include "base/Error.h"
#include "io/SizingReader.h"

#include <gtest/gtest.h>

using namespace surfacemaps;

namespace
{
std::string errorOf(const std::string& text, std::size_t vertices)
{
  try
  {
    parseSizing(text, "s.txt", vertices);
  }
  catch (const InputError& e)
  {
    return e.what();
  }
  return "";
}
} // namespace

TEST(SizingReader, OneLengthPerVertex)
{
  EXPECT_EQ(parseSizing("# lengths\n0.5\n\n2e-2\n+3\n", "s.txt", 3),
    (std::vector<double>{ 0.5, 0.02, 3.0 }));
}

TEST(SizingReader, MalformedFilesNameTheLine)
{
  struct Case
  {
    const char* Text;
    std::size_t Vertices;
    const char* Message;
  };
  for (const Case& c : {
         Case{ "1\n0\n", 2, "s.txt:2: the target edge length '0' (vertex 1) is not a finite positive number" },
         Case{ "1\n-2\n", 2, "s.txt:2: the target edge length '-2' (vertex 1)" },
         Case{ "1\nnan\n", 2, "s.txt:2: the target edge length 'nan'" },
         Case{ "1\ninf\n", 2, "s.txt:2: the target edge length 'inf'" },
         Case{ "1\nx\n", 2, "s.txt:2: expected a target edge length, got 'x'" },
         Case{ "1 2\n", 2, "s.txt:1: expected one value per line, got '1 2'" },
         Case{ "1\n2\n3\n", 2, "s.txt:3: more values than the mesh's 2 vertices" },
         Case{ "1\n", 2, "s.txt:1: the file ends after 1 values, but the mesh has 2 vertices" },
       })
  {
    const std::string error = errorOf(c.Text, c.Vertices);
    EXPECT_NE(error.find(c.Message), std::string::npos) << "'" << c.Text << "': " << error;
  }
}
