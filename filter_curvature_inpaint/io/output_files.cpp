#include "io/output_files.h"

#include <QBuffer>
#include <QByteArray>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <sys/stat.h>
#include <unistd.h>

namespace curvature_inpaint {

namespace {

/// The folder that holds `path` ("." for a bare file name).
std::string FolderOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

bool IsFolder(const std::string& path) {
  struct stat s;
  return ::stat(path.c_str(), &s) == 0 && S_ISDIR(s.st_mode);
}

} // namespace

bool SameFile(const std::string& a, const std::string& b) {
  struct stat sa, sb;
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

std::string WriteTarget(const std::string& path) {
  struct stat s;
  if (::lstat(path.c_str(), &s) != 0 || !S_ISLNK(s.st_mode)) return path;
  char resolved[PATH_MAX];
  return ::realpath(path.c_str(), resolved) ? std::string(resolved) : path;
}

void CheckWritable(const std::string& path) {
  if (path.empty()) throw OutputError("an output path is empty");
  if (IsFolder(path)) throw OutputError(path + ": is a folder; give a file name");
  const std::string folder = FolderOf(path);
  if (!IsFolder(folder)) throw OutputError(path + ": the folder " + folder + " does not exist");
  if (::access(folder.c_str(), W_OK | X_OK) != 0)
    throw OutputError(path + ": the folder " + folder + " is not writable");
  if (::access(path.c_str(), F_OK) == 0 && ::access(path.c_str(), W_OK) != 0)
    throw OutputError(path + ": the file exists and is not writable");
}

void CheckMeshOutput(const std::string& input, const std::string& output, bool in_place) {
  if (!in_place && SameFile(input, output))
    throw OutputError(output + ": is the input scan; give another output file, or --in-place to "
                               "replace the scan");
  CheckWritable(WriteTarget(output));
}

void CheckFolderWritable(const std::string& dir) {
  if (dir.empty()) throw OutputError("an output folder is empty");
  std::string existing = dir;
  while (::access(existing.c_str(), F_OK) != 0 && existing != "." && existing != "/")
    existing = FolderOf(existing);
  if (!IsFolder(existing))
    throw OutputError(
        dir + ": " +
        (existing == dir ? "is a file, not a folder" : existing + " is a file, not a folder"));
  if (::access(existing.c_str(), W_OK | X_OK) != 0)
    throw OutputError(dir + ": the folder " + existing + " is not writable");
}

void WriteFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string target = WriteTarget(path);
  const std::string tmp = target + ".part" + std::to_string(::getpid());
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  const bool written = f && std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
  const bool closed = f && std::fclose(f) == 0;
  if (!written || !closed || std::rename(tmp.c_str(), target.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw OutputError(path + ": cannot write the file");
  }
}

void SavePngAtomically(const QImage& image, const std::string& path) {
  QByteArray png;
  QBuffer buffer(&png);
  if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG"))
    throw OutputError(path + ": cannot encode the image");
  WriteFileAtomically(path, std::string(png.constData(), size_t(png.size())));
}

} // namespace curvature_inpaint
