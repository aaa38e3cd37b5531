// The command line: NumPy's .npz archive, the form in which arrays reach a
// user's numpy (numpy.load) or R (reticulate, RcppCNPy).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace surfacemap
{

/// An uncompressed .npz archive built in memory, as numpy.savez writes one:
/// a zip file with one member <name>.npy per array (.npy format 1.0,
/// little-endian, C order). numpy.load reads it without allow_pickle.
///
/// Built in memory because a map directory records the size and checksum of
/// the bytes it writes (MapWriter); the zip container is written here because
/// the zip library that comes with zlib (minizip) writes through its own file
/// callbacks only. The archive is limited to members below 4 GiB (no Zip64);
/// larger arrays throw std::length_error.
class NumpyArchive
{
public:
  /// A float64 array of the given shape; `values` in C order, as many as
  /// the shape's product (std::invalid_argument otherwise).
  void addDoubles(
    const std::string& name, const std::vector<std::size_t>& shape, const std::vector<double>& values);

  /// An int64 array of the given shape (as addDoubles).
  void addIntegers(const std::string& name,
    const std::vector<std::size_t>& shape,
    const std::vector<std::int64_t>& values);

  /// A one-dimensional unicode string array (numpy dtype '<Un', n the
  /// longest string's code points) from UTF-8 strings; an invalid byte
  /// sequence becomes U+FFFD.
  void addStrings(const std::string& name, const std::vector<std::string>& values);

  /// The archive's bytes.
  std::string bytes() const;

private:
  void addMember(const std::string& name,
    const std::string& descr,
    const std::vector<std::size_t>& shape,
    const std::string& data);

  struct Member
  {
    std::string name;
    std::string data;
  };
  std::vector<Member> Members;
};

} // namespace surfacemap
