// The `surfacemap` command line: JSON documents (report.json, summary.json)
// built and read with jsoncpp, the JSON library VTK itself uses; how a
// number is written, how a document becomes text, how a file is read.
#pragma once

#include "vtk_jsoncpp.h"

#include <string>

namespace surfacemap
{

/// `value` as a JSON number: null if not finite (JSON has no infinity or
/// NaN), an integer if it is one (a count reads back as an integer), else a
/// double, which jsonText writes so that it reads back the same.
Json::Value jsonNumber(double value);

/// `document` as text, indented by two spaces, with a final newline:
/// doubles with 17 significant digits (enough to read back every double
/// exactly), strings in UTF-8 as given.
std::string jsonText(const Json::Value& document);

/// The JSON document in the file `path`. Throws std::runtime_error
/// "<path> is missing: <needed>" when it cannot be opened, or "<path> is
/// not valid JSON: <the parser's message>".
Json::Value readJsonFile(const std::string& path, const std::string& needed);

} // namespace surfacemap
