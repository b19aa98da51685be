#include "pirouette/io/run_log.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "pirouette/core/input_error.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/io/image_io.h"
#include "pirouette/robot/line_protocol.h"
#include "pirouette/robot/robot_error.h"

namespace pirouette::io {
namespace {

namespace fs = std::filesystem;

constexpr const char* kFormat = "pirouette-log/1";
constexpr const char* kHeader = "index,time_s,x,y,heading_deg,motion,blocked_leg_m";

std::string FramePath(const std::string& dir, int index) {
  return (fs::path(dir) / "frames" / fmt::format("{:06d}.png", index)).string();
}

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

double ParseNumber(const std::string& text, const std::string& file, int line,
                   const std::string& field) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw core::InputError(file, line, field, "'" + text + "' is not a number");
  }
  return value;
}

RunLogInfo ReadInfo(const std::string& path) {
  RunLogInfo info;
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw core::InputError(path, e.mark.line + 1, "", e.msg);
  }
  const auto number = [&](const YAML::Node& node, const std::string& field) {
    double value = 0.0;
    try {
      value = node.as<double>();
    } catch (const YAML::Exception&) {
      throw core::InputError(path, node.Mark().line + 1, field, "must be a number");
    }
    if (!std::isfinite(value)) {
      throw core::InputError(path, node.Mark().line + 1, field, "must be a finite number");
    }
    return value;
  };
  // A section (robot, map, source): absent, empty or a map of its fields.
  const auto section = [&](const char* key) {
    const YAML::Node node = root[key];
    if (node && !node.IsMap() && !node.IsNull()) {
      throw core::InputError(path, node.Mark().line + 1, key, "must be a map of fields");
    }
    return node;
  };
  if (!root.IsMap() || !root["format"] || root["format"].as<std::string>("") != kFormat) {
    throw core::InputError(path, 0, "format", std::string("must be ") + kFormat);
  }
  if (const YAML::Node robot = section("robot"); robot && robot["radius"]) {
    info.radius_m = number(robot["radius"], "robot.radius");
  }
  if (const YAML::Node map = section("map")) {
    if (map["cell"]) info.cell_m = number(map["cell"], "map.cell");
    if (map["max_range"]) info.max_range_m = number(map["max_range"], "map.max_range");
    if (map["method"]) info.method = map["method"].as<std::string>("");
    if (map["localize"]) info.localize = map["localize"].as<std::string>("");
    if (const YAML::Node model = map["odometry_model"]) {
      if (!model.IsSequence() || model.size() != 2) {
        throw core::InputError(path, model.Mark().line + 1, "map.odometry_model",
                               "must be [translation, rotation], fractions >= 0");
      }
      const double t = number(model[0], "map.odometry_model");
      const double r = number(model[1], "map.odometry_model");
      if (!(t >= 0.0 && t <= 1.0) || !(r >= 0.0 && r <= 1.0)) {
        throw core::InputError(path, model.Mark().line + 1, "map.odometry_model",
                               "fractions must be between 0 and 1");
      }
      info.odometry_model = std::array<double, 2>{t, r};
    }
  }
  if (const YAML::Node source = section("source")) {
    if (source["world"]) info.world = source["world"].as<std::string>("");
    if (source["seed"]) {
      try {
        info.seed = source["seed"].as<std::uint64_t>();
      } catch (const YAML::Exception&) {
        throw core::InputError(path, source["seed"].Mark().line + 1, "source.seed",
                               "must be a whole number >= 0");
      }
    }
  }
  return info;
}

std::string InfoText(const RunLogInfo& info) {
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << "format" << YAML::Value << kFormat;
  out << YAML::Key << "robot" << YAML::Value << YAML::BeginMap << YAML::Key << "radius"
      << YAML::Value << info.radius_m << YAML::EndMap;
  out << YAML::Key << "map" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "cell" << YAML::Value << info.cell_m;
  out << YAML::Key << "max_range" << YAML::Value << info.max_range_m;
  out << YAML::Key << "method" << YAML::Value << info.method;
  if (!info.localize.empty()) out << YAML::Key << "localize" << YAML::Value << info.localize;
  if (info.odometry_model) {
    out << YAML::Key << "odometry_model" << YAML::Value << YAML::Flow << YAML::BeginSeq
        << (*info.odometry_model)[0] << (*info.odometry_model)[1] << YAML::EndSeq;
  }
  out << YAML::EndMap;
  if (!info.world.empty()) {
    out << YAML::Key << "source" << YAML::Value << YAML::BeginMap << YAML::Key << "world"
        << YAML::Value << info.world << YAML::Key << "seed" << YAML::Value << info.seed
        << YAML::EndMap;
  }
  out << YAML::EndMap;
  return std::string("# A pirouette run log (docs/run-log.md).\n") + out.c_str() + "\n";
}

}  // namespace

std::string MotionText(const std::vector<core::MoveOutcome>& motions) {
  std::string text;
  for (const core::MoveOutcome& m : motions) {
    if (!text.empty()) text += ';';
    if (m.requested.kind == core::Move::Kind::kTurn) {
      text += "turn " + robot::FormatDegrees(m.achieved);
    } else {
      text += fmt::format("straight {}{}", m.achieved, m.stopped_at_contact ? " contact" : "");
    }
  }
  return text;
}

RunLogWriter::RunLogWriter(const std::string& dir, const camera::CameraModel& camera,
                           const RunLogInfo& info)
    : dir_(dir) {
  const fs::path root(dir);
  if (fs::exists(root / "frames.csv")) {
    throw core::InputError(dir, 0, "--record",
                           "already holds a run log; choose another folder or remove it");
  }
  std::error_code error;
  fs::create_directories(root / "frames", error);
  if (error) {
    throw core::InputError(dir, 0, "--record", "cannot create the folder: " + error.message());
  }
  WriteFileAtomically((root / "camera.yaml").string(), io::CameraFileText(camera));
  WriteFileAtomically((root / "log.yaml").string(), InfoText(info));
  csv_.open(root / "frames.csv");
  if (!csv_) throw std::runtime_error("cannot write " + (root / "frames.csv").string());
  csv_ << kHeader << '\n' << std::flush;
}

RunLogWriter::~RunLogWriter() {
  try {
    Close();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw
  }
}

void RunLogWriter::AddFrame(const robot::Frame& frame,
                            const std::vector<core::MoveOutcome>& motions) {
  if (closed_) throw std::logic_error("RunLogWriter: frame after Close");
  FlushRow();
  const int index = next_index_++;
  WritePng(FramePath(dir_, index), frame.image);
  const core::Pose2& p = frame.odometry;
  pending_ = fmt::format("{},{},{},{},{},{},", index, frame.time_s, p.x(), p.y(),
                         robot::FormatDegrees(p.heading()), MotionText(motions));
}

void RunLogWriter::MarkBlocked(double leg_m) {
  if (pending_) pending_blocked_ = leg_m;
}

void RunLogWriter::Close() {
  if (closed_) return;
  FlushRow();
  closed_ = true;
  csv_.close();
}

void RunLogWriter::FlushRow() {
  if (!pending_) return;
  csv_ << *pending_;
  if (pending_blocked_) csv_ << fmt::format("{}", *pending_blocked_);
  csv_ << '\n' << std::flush;
  if (!csv_) throw std::runtime_error("cannot write " + dir_ + "/frames.csv");
  pending_.reset();
  pending_blocked_.reset();
}

RunLog ReadRunLog(const std::string& dir) {
  const fs::path root(dir);
  if (!fs::is_directory(root)) throw core::InputError(dir, 0, "--log", "no such folder");
  RunLog log{dir,
             fs::exists(root / "log.yaml") ? ReadInfo((root / "log.yaml").string()) : RunLogInfo{},
             io::LoadCameraFile((root / "camera.yaml").string()),
             {},
             {}};
  const std::string csv_path = (root / "frames.csv").string();
  std::ifstream csv(csv_path);
  if (!csv) throw core::InputError(csv_path, 0, "", "no such file");
  std::string line;
  int line_no = 1;
  if (std::getline(csv, line) && csv.eof()) {
    throw core::InputError(csv_path, 1, "header",
                           "holds no frames: the log was cut inside its header line");
  }
  if (!csv || line.rfind("index,time_s,x,y,heading_deg", 0) != 0) {
    throw core::InputError(
        csv_path, 1, "header",
        std::string("must start with index,time_s,x,y,heading_deg (") + kHeader + ")");
  }
  while (std::getline(csv, line)) {
    ++line_no;
    if (csv.eof()) {
      // Every row the writer appends ends in a line end: one without it is
      // where the writing stopped (a run killed, a copy cut short), and may
      // hold a number cut in two that would read as another number.
      log.cut = fmt::format("{} line {}: a partial row (no line end): the log was cut there",
                            csv_path, line_no);
      break;
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const std::vector<std::string> f = SplitCsv(line);
    if (f.size() < 5 || f.size() > 7) {
      throw core::InputError(csv_path, line_no, "",
                             fmt::format("{} fields; a row has 5 to 7 ({})", f.size(), kHeader));
    }
    RunLogRow row;
    const double index = ParseNumber(f[0], csv_path, line_no, "index");
    if (index < 0 || index != std::floor(index) || index > 1e8) {
      throw core::InputError(csv_path, line_no, "index", "must be a whole number >= 0");
    }
    row.index = static_cast<int>(index);
    row.time_s = ParseNumber(f[1], csv_path, line_no, "time_s");
    double heading_rad = 0.0;
    try {
      heading_rad = robot::ParseDegrees(f[4]);  // bit-exact back to the radians written
    } catch (const robot::RobotError&) {
      throw core::InputError(csv_path, line_no, "heading_deg", "'" + f[4] + "' is not a number");
    }
    row.odometry = core::Pose2(ParseNumber(f[2], csv_path, line_no, "x"),
                               ParseNumber(f[3], csv_path, line_no, "y"), heading_rad);
    if (f.size() > 5) {
      row.motion = f[5];
      const std::size_t last = row.motion.rfind(';');
      const std::string last_motion =
          last == std::string::npos ? row.motion : row.motion.substr(last + 1);
      row.contact = last_motion.find("contact") != std::string::npos;
    }
    if (f.size() > 6 && !f[6].empty()) {
      row.blocked_leg_m = ParseNumber(f[6], csv_path, line_no, "blocked_leg_m");
    }
    log.rows.push_back(std::move(row));
  }
  if (log.rows.empty()) {
    throw core::InputError(csv_path, 0, "",
                           log.cut.empty() ? "holds no frames" : "holds no whole row: " + log.cut);
  }
  return log;
}

robot::Frame ReadLogFrame(const RunLog& log, const RunLogRow& row) {
  const std::string path = FramePath(log.dir, row.index);
  robot::Frame frame;
  frame.image = ReadImage(path);
  if (frame.image.width() != log.camera.width() || frame.image.height() != log.camera.height()) {
    throw core::InputError(
        path, 0, "",
        fmt::format("the image is {}x{}, the log's camera {}x{}", frame.image.width(),
                    frame.image.height(), log.camera.width(), log.camera.height()));
  }
  frame.odometry = row.odometry;
  frame.time_s = row.time_s;
  return frame;
}

}  // namespace pirouette::io
