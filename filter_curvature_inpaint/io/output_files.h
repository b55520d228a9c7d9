// Where the command-line tool writes its results: checked before any work is done, never
// over the input unless the user asked for it, and always whole (a temporary file beside the
// target, renamed into place), so that a failure or a kill loses nothing.
#pragma once

#include <QImage>

#include <stdexcept>
#include <string>

namespace curvature_inpaint {

/// A result that cannot, or must not, be written; the message names the path and why.
class OutputError : public std::runtime_error {
public:
  explicit OutputError(const std::string& what) : std::runtime_error(what) {}
};

/// Whether `a` and `b` name the same existing file, also through symbolic or hard links.
bool SameFile(const std::string& a, const std::string& b);

/// The path a result for `path` is written to: `path` itself, or, where it is a symbolic link,
/// the file the link points to (so that replacing a linked scan replaces the scan, not the link).
std::string WriteTarget(const std::string& path);

/// Checks that a file can be written at `path`: its folder exists and is writable, and `path`
/// is not a folder. Throws OutputError naming the folder or the path.
void CheckWritable(const std::string& path);

/// Checks that `output` can receive the mesh made from `input`: as CheckWritable, and not the
/// input file itself unless `in_place`. Throws OutputError.
void CheckMeshOutput(const std::string& input, const std::string& output, bool in_place);

/// Checks that the folder `dir` can receive results: it is a writable folder, or it is missing
/// and could be made (its nearest existing parent is a writable folder). Nothing is created.
/// Throws OutputError.
void CheckFolderWritable(const std::string& dir);

/// Writes `bytes` to `path` whole or not at all: into a temporary file beside it, renamed into
/// place. Throws OutputError.
void WriteFileAtomically(const std::string& path, const std::string& bytes);

/// Writes `image` as a PNG to `path`, whole or not at all (see WriteFileAtomically). Throws
/// OutputError.
void SavePngAtomically(const QImage& image, const std::string& path);

} // namespace curvature_inpaint
