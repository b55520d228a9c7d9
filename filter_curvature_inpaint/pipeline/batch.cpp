#include "pipeline/batch.h"

#include "io/mesh_io.h"
#include "io/output_files.h"
#include "pipeline/pipeline.h"

#include <vcg_ext/parallel_for.h>

#include <QCryptographicHash>
#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>
#include <unistd.h>

namespace curvature_inpaint {

namespace {

bool IsMeshFile(const QString& name) {
  const QString s = QFileInfo(name).suffix().toLower();
  return s == "ply" || s == "obj" || s == "off" || s == "stl";
}

std::string Sha256(const std::string& bytes) {
  QCryptographicHash hash(QCryptographicHash::Sha256);
  const size_t chunk = size_t(1) << 30; // Qt 5 takes an int length
  for (size_t at = 0; at < bytes.size(); at += chunk)
    hash.addData(bytes.data() + at, int(std::min(chunk, bytes.size() - at)));
  return hash.result().toHex().toStdString();
}

/// What makes two runs of a scan the same: its bytes and its options.
std::string Key(const std::string& sha256, const std::vector<std::string>& options) {
  std::string k = sha256;
  for (const auto& o : options) k += '\x1f' + o;
  return k;
}

std::string ResultsName(const BatchParams& p) {
  return p.shards == 1 ? "results.jsonl"
                       : "results." + std::to_string(p.shard + 1) + "-of-" +
                             std::to_string(p.shards) + ".jsonl";
}

/// Every results line of every shard in `outdir`, oldest first within each file.
std::vector<QJsonObject> ReadResults(const std::string& outdir) {
  std::vector<QJsonObject> lines;
  const QStringList files =
      QDir(QString::fromStdString(outdir)).entryList({"results*.jsonl"}, QDir::Files, QDir::Name);
  for (const QString& name : files) {
    QFile f(QDir(QString::fromStdString(outdir)).filePath(name));
    if (!f.open(QIODevice::ReadOnly)) continue;
    for (const QByteArray& line : f.readAll().split('\n')) {
      // A line cut short by a kill is not a result.
      const QJsonDocument doc = QJsonDocument::fromJson(line);
      if (doc.isObject()) lines.push_back(doc.object());
    }
  }
  return lines;
}

std::vector<std::string> Split(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

std::string Seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", s);
  return buf;
}

} // namespace

std::vector<BatchScan> ReadManifest(const std::string& manifest) {
  std::vector<BatchScan> scans;
  const QFileInfo info(QString::fromStdString(manifest));
  if (info.isDir()) {
    const QDir dir(info.absoluteFilePath());
    for (const QString& name : dir.entryList(QDir::Files, QDir::Name))
      if (IsMeshFile(name)) scans.push_back({dir.filePath(name).toStdString(), {}});
  } else {
    QFile f(info.absoluteFilePath());
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
      throw std::runtime_error("cannot read the manifest " + manifest);
    const QDir base = info.absoluteDir();
    for (const QByteArray& raw : f.readAll().split('\n')) {
      std::string line = raw.toStdString();
      line = line.substr(0, line.find('#'));
      std::vector<std::string> words = Split(line);
      if (words.empty()) continue;
      const QString path = QString::fromStdString(words[0]);
      scans.push_back(
          {QDir::isAbsolutePath(path) ? path.toStdString() : base.filePath(path).toStdString(),
           std::vector<std::string>(words.begin() + 1, words.end())});
    }
  }
  std::set<std::string> names;
  for (const auto& s : scans)
    if (!names.insert(QFileInfo(QString::fromStdString(s.input)).fileName().toStdString()).second)
      throw std::runtime_error("two scans of the manifest are named " +
                               QFileInfo(QString::fromStdString(s.input)).fileName().toStdString() +
                               ": their results would overwrite each other");
  return scans;
}

namespace {

/// What an earlier run into `outdir` finished: successful lines whose output is still there
/// (Key of the scan's SHA-256 and options).
std::set<std::string> FinishedBefore(const std::string& outdir) {
  std::set<std::string> finished;
  for (const QJsonObject& o : ReadResults(outdir))
    if (o.value("status").toString() == "ok" &&
        QFileInfo::exists(QString::fromStdString(outdir) + "/" + o.value("output").toString())) {
      std::vector<std::string> options;
      for (const auto& v : o.value("options").toArray())
        options.push_back(v.toString().toStdString());
      finished.insert(Key(o.value("sha256").toString().toStdString(), options));
    }
  return finished;
}

/// One progress bar line (redrawn in place): scans reported, failed, rate and time left.
void PrintProgressBar(const BatchSummary& summary, int reported,
                      std::chrono::steady_clock::time_point start) {
  const double minutes =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / 60;
  const double rate = minutes > 0 ? (reported - summary.skipped) / minutes : 0;
  const int width = 30, filled = summary.scans ? width * reported / summary.scans : width;
  const double left = rate > 0 ? (summary.scans - reported) / rate : 0;
  std::fprintf(stderr, "\r[%s%s] %d/%d scans, %d failed, %.1f per minute, %.0f min left ",
               std::string(size_t(filled), '#').c_str(),
               std::string(size_t(width - filled), '-').c_str(), reported, summary.scans,
               summary.failed, rate, left);
  if (reported == summary.scans) std::fprintf(stderr, "\n");
}

/// Each hole's line in the results: its kind, and where it was validated the choice and each
/// candidate's error.
QJsonArray HolesJson(const HoleFillResult& result) {
  QJsonArray holes;
  for (size_t k = 0; k < result.holes.size(); ++k) {
    const HoleFillReport& r = result.holes[k];
    QJsonObject h;
    h.insert("hole", int(k + 1));
    const ValidationRecord& v = r.choice.validation;
    const FillKind kind = r.choice.problem.empty() ? r.kind : FillKind::kCoarse;
    h.insert("kind", FillKindName(kind));
    if (v.HasChoice()) {
      h.insert("choice", QString::fromStdString(TriedFillName(v.Chosen())));
      QJsonObject errors;
      for (size_t c = 0; c < v.candidates.size(); ++c)
        errors.insert(QString::fromStdString(TriedFillName(v.candidates[c])), v.errors[c]);
      h.insert("validation", errors);
    }
    holes.append(h);
  }
  return holes;
}

/// Fills the scan read from `input` (its `bytes`, released once loaded) and writes it to
/// `output` by way of outdir's hidden folder, renamed into place, so that a kill leaves nothing
/// half-written among the results. Sets the line's status, counts and holes; returns what to
/// tell the user. Throws what LoadMesh, FillHoles and SaveMesh throw.
std::string FillScan(const std::string& input, std::string& bytes, const HoleFillParams& p,
                     const std::string& output, const std::string& outdir, QJsonObject& line) {
  CMeshO m;
  const int mask = LoadMesh(input, bytes, m);
  std::string().swap(bytes);
  const HoleFillResult result = FillHoles(m, p);
  SaveMesh(output, m, mask, outdir + "/.partial");
  const HoleCensus left = CountHoles(m);
  line.insert("status", "ok");
  line.insert("holes_filled", result.coarse.FilledCount());
  line.insert("holes_left", int(left.loop_edges.size()));
  line.insert("holes", HolesJson(result));
  return "filled " + std::to_string(result.coarse.FilledCount()) + " hole(s) (" +
         std::to_string(left.loop_edges.size()) + " left)";
}

} // namespace

BatchSummary RunBatch(const std::vector<BatchScan>& all, const BatchParams& params,
                      const FillOptionParser& parse) {
  if (params.shards < 1 || params.shard < 0 || params.shard >= params.shards)
    throw std::runtime_error("the shard must be K/N with 1 <= K <= N");
  if (!QDir().mkpath(QString::fromStdString(params.outdir + "/.partial")))
    throw std::runtime_error("cannot create " + params.outdir);
  std::vector<BatchScan> scans;
  for (size_t i = 0; i < all.size(); ++i)
    if (int(i % size_t(params.shards)) == params.shard) scans.push_back(all[i]);
  const std::set<std::string> finished = FinishedBefore(params.outdir);
  const std::string results_path = params.outdir + "/" + ResultsName(params);
  std::FILE* results = std::fopen(results_path.c_str(), "a");
  if (!results) throw std::runtime_error("cannot write " + results_path);

  const int cores = vcg_ext::ThreadCount(0);
  const int jobs = std::max(1, std::min(params.jobs, int(scans.size())));
  BatchSummary summary;
  summary.scans = int(scans.size());
  std::mutex mutex;
  std::atomic<size_t> next{0};
  int reported = 0;
  const auto start = std::chrono::steady_clock::now();
  auto report = [&](const std::string& name, const std::string& what) {
    // Called with `mutex` held.
    ++reported;
    if (params.progress_bar)
      PrintProgressBar(summary, reported, start);
    else
      std::fprintf(stderr, "batch: %d/%d %s: %s\n", reported, summary.scans, name.c_str(),
                   what.c_str());
  };
  auto work = [&] {
    for (size_t i = next++; i < scans.size(); i = next++) {
      const BatchScan& scan = scans[i];
      const QFileInfo in(QString::fromStdString(scan.input));
      const std::string name = in.fileName().toStdString();
      std::vector<std::string> options = params.options;
      options.insert(options.end(), scan.options.begin(), scan.options.end());
      // Read once: hashed to know whether it was done before, then loaded from the same bytes.
      std::string scan_bytes, unreadable;
      try {
        scan_bytes = ReadMeshFile(scan.input);
      } catch (const MeshIoError& e) {
        unreadable = e.what();
      }
      const std::string sha = unreadable.empty() ? Sha256(scan_bytes) : "";
      if (!sha.empty() && finished.count(Key(sha, options))) {
        std::lock_guard<std::mutex> lock(mutex);
        ++summary.skipped;
        report(name, "done before, skipped");
        continue;
      }
      const auto t = std::chrono::steady_clock::now();
      QJsonObject line;
      line.insert("input", QString::fromStdString(scan.input));
      line.insert("sha256", QString::fromStdString(sha));
      QJsonArray opts;
      for (const auto& o : options) opts.append(QString::fromStdString(o));
      line.insert("options", opts);
      line.insert("output", QString::fromStdString(name));
      std::string what;
      try {
        if (!unreadable.empty()) throw std::runtime_error(unreadable);
        HoleFillParams p = parse(options);
        if (std::find(options.begin(), options.end(), "--threads") == options.end())
          p.images.coarse.threads = std::max(1, cores / jobs);
        what = FillScan(scan.input, scan_bytes, p, params.outdir + "/" + name, params.outdir, line);
      } catch (const std::exception& e) {
        line.insert("status", "failed");
        line.insert("error", QString::fromStdString(e.what()));
        what = std::string("failed: ") + e.what();
      }
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
      line.insert("seconds", seconds);
      line.insert("finished", QDateTime::currentDateTimeUtc().toString(Qt::ISODate));
      const QByteArray bytes = QJsonDocument(line).toJson(QJsonDocument::Compact) + '\n';
      std::lock_guard<std::mutex> lock(mutex);
      // The line is on disk before the next scan starts: a kill loses at most the scans that
      // were running.
      std::fwrite(bytes.constData(), 1, size_t(bytes.size()), results);
      std::fflush(results);
      fsync(fileno(results));
      if (line.value("status").toString() == "ok")
        ++summary.done;
      else
        ++summary.failed;
      report(name, what + " in " + Seconds(seconds) + " s");
    }
  };
  std::vector<std::thread> workers;
  for (int j = 1; j < jobs; ++j) workers.emplace_back(work);
  work();
  for (auto& w : workers) w.join();
  std::fclose(results);
  return summary;
}

int SummarizeBatch(const std::string& outdir) {
  // The latest result of each scan, whichever shard wrote it.
  std::map<std::string, QJsonObject> latest;
  for (const QJsonObject& o : ReadResults(outdir)) {
    const std::string input = o.value("input").toString().toStdString();
    auto it = latest.find(input);
    if (it == latest.end() ||
        it->second.value("finished").toString() <= o.value("finished").toString())
      latest[input] = o;
  }
  if (latest.empty()) throw std::runtime_error("no results in " + outdir);
  int ok = 0, failed = 0, filled = 0, left = 0;
  std::vector<double> seconds;
  std::ostringstream csv, failures;
  csv << "input,status,holes_filled,holes_left,seconds,error\n";
  for (const auto& kv : latest) {
    const QJsonObject& o = kv.second;
    const bool good = o.value("status").toString() == "ok";
    ok += good, failed += !good;
    filled += o.value("holes_filled").toInt();
    left += o.value("holes_left").toInt();
    seconds.push_back(o.value("seconds").toDouble());
    std::string error = o.value("error").toString().toStdString();
    for (char& c : error)
      if (c == '"' || c == '\n' || c == '|') c = '\'';
    csv << '"' << kv.first << "\"," << (good ? "ok" : "failed") << ','
        << o.value("holes_filled").toInt() << ',' << o.value("holes_left").toInt() << ','
        << Seconds(o.value("seconds").toDouble()) << ",\"" << error << "\"\n";
    if (!good)
      failures << "| " << QFileInfo(QString::fromStdString(kv.first)).fileName().toStdString()
               << " | " << error << " |\n";
  }
  std::sort(seconds.begin(), seconds.end());
  std::printf("| scans | filled | failed | holes filled | holes left | s per scan (median) | "
              "s per scan (max) |\n|---|---|---|---|---|---|---|\n");
  std::printf("| %zu | %d | %d | %d | %d | %s | %s |\n", latest.size(), ok, failed, filled, left,
              Seconds(seconds[seconds.size() / 2]).c_str(), Seconds(seconds.back()).c_str());
  if (failed) std::printf("\n| failed scan | reason |\n|---|---|\n%s", failures.str().c_str());
  const std::string path = outdir + "/summary.csv";
  WriteFileAtomically(path, csv.str());
  std::fprintf(stderr, "wrote %s\n", path.c_str());
  return failed;
}

} // namespace curvature_inpaint
