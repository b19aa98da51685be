#include "pirouette/robot/ros2/ros2_msg_schema.h"

#include <set>
#include <vector>

namespace pirouette::robot::ros2 {

namespace {

struct Definition {
  std::string_view name;    // package/Type
  std::string_view fields;  // one field a line
  std::vector<std::string_view> uses;
};

const std::vector<Definition>& Definitions() {
  static const std::vector<Definition> kDefinitions = {
      {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n", {}},
      {"std_msgs/Header",
       "builtin_interfaces/Time stamp\nstring frame_id\n",
       {"builtin_interfaces/Time"}},
      {"std_msgs/String", "string data\n", {}},
      {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n", {}},
      {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n", {}},
      {"geometry_msgs/Quaternion", "float64 x\nfloat64 y\nfloat64 z\nfloat64 w\n", {}},
      {"geometry_msgs/Pose",
       "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n",
       {"geometry_msgs/Point", "geometry_msgs/Quaternion"}},
      {"geometry_msgs/PoseStamped",
       "std_msgs/Header header\ngeometry_msgs/Pose pose\n",
       {"std_msgs/Header", "geometry_msgs/Pose"}},
      {"geometry_msgs/Transform",
       "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n",
       {"geometry_msgs/Vector3", "geometry_msgs/Quaternion"}},
      {"geometry_msgs/TransformStamped",
       "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/Transform transform\n",
       {"std_msgs/Header", "geometry_msgs/Transform"}},
      {"nav_msgs/MapMetaData",
       "builtin_interfaces/Time map_load_time\nfloat32 resolution\nuint32 width\nuint32 "
       "height\ngeometry_msgs/Pose origin\n",
       {"builtin_interfaces/Time", "geometry_msgs/Pose"}},
      {"nav_msgs/OccupancyGrid",
       "std_msgs/Header header\nnav_msgs/MapMetaData info\nint8[] data\n",
       {"std_msgs/Header", "nav_msgs/MapMetaData"}},
      {"nav_msgs/Path",
       "std_msgs/Header header\ngeometry_msgs/PoseStamped[] poses\n",
       {"std_msgs/Header", "geometry_msgs/PoseStamped"}},
      {"sensor_msgs/Image",
       "std_msgs/Header header\nuint32 height\nuint32 width\nstring encoding\nuint8 "
       "is_bigendian\nuint32 step\nuint8[] data\n",
       {"std_msgs/Header"}},
      {"sensor_msgs/CompressedImage",
       "std_msgs/Header header\nstring format\nuint8[] data\n",
       {"std_msgs/Header"}},
      {"tf2_msgs/TFMessage",
       "geometry_msgs/TransformStamped[] transforms\n",
       {"geometry_msgs/TransformStamped"}},
  };
  return kDefinitions;
}

const Definition* Find(std::string_view name) {
  for (const Definition& d : Definitions()) {
    if (d.name == name) return &d;
  }
  return nullptr;
}

// Appends the types `d` uses, depth first, each once.
void AppendUses(const Definition& d, std::set<std::string_view>& written, std::string& text) {
  for (const std::string_view use : d.uses) {
    if (!written.insert(use).second) continue;
    const Definition* used = Find(use);
    text += std::string(80, '=');
    text += "\nMSG: ";
    text += used->name;
    text += '\n';
    text += used->fields;
    AppendUses(*used, written, text);
  }
}

}  // namespace

std::optional<std::string> Ros2MsgSchema(std::string_view type) {
  constexpr std::string_view kMsg = "/msg/";
  const std::size_t at = type.find(kMsg);
  if (at == std::string_view::npos) return std::nullopt;
  const std::string name =
      std::string(type.substr(0, at)) + "/" + std::string(type.substr(at + kMsg.size()));
  const Definition* d = Find(name);
  if (d == nullptr) return std::nullopt;
  std::string text(d->fields);
  std::set<std::string_view> written{d->name};
  AppendUses(*d, written, text);
  return text;
}

}  // namespace pirouette::robot::ros2
