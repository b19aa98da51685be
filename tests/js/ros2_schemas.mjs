// The ros2msg schemas of the live view's channels, as foxglove_bridge and
// MCAP write them: the top message's definition, then each type it uses after
// a line of 80 '=' and "MSG: pkg/Type". Only the mock server (mock_server.mjs)
// uses them; the tests read the schemas the real server advertises.

const RULE = "=".repeat(80);

const DEFS = {
  "builtin_interfaces/Time": "int32 sec\nuint32 nanosec\n",
  "std_msgs/Header": "builtin_interfaces/Time stamp\nstring frame_id\n",
  "geometry_msgs/Point": "float64 x\nfloat64 y\nfloat64 z\n",
  "geometry_msgs/Vector3": "float64 x\nfloat64 y\nfloat64 z\n",
  "geometry_msgs/Quaternion": "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n",
  "geometry_msgs/Pose": "Point position\nQuaternion orientation\n",
  "geometry_msgs/PoseStamped": "std_msgs/Header header\nPose pose\n",
  "geometry_msgs/Transform": "Vector3 translation\nQuaternion rotation\n",
  "geometry_msgs/TransformStamped": "std_msgs/Header header\nstring child_frame_id\nTransform transform\n",
  "nav_msgs/MapMetaData":
    "builtin_interfaces/Time map_load_time\nfloat32 resolution\nuint32 width\nuint32 height\ngeometry_msgs/Pose origin\n",
  "nav_msgs/OccupancyGrid": "std_msgs/Header header\nMapMetaData info\nint8[] data\n",
  "nav_msgs/Path": "std_msgs/Header header\ngeometry_msgs/PoseStamped[] poses\n",
  "sensor_msgs/CompressedImage": "std_msgs/Header header\nstring format\nuint8[] data\n",
  "std_msgs/String": "string data\n",
  "tf2_msgs/TFMessage": "geometry_msgs/TransformStamped[] transforms\n",
};

// The types each one uses, in the order the schema lists them.
const DEPS = {
  "nav_msgs/OccupancyGrid": ["std_msgs/Header", "builtin_interfaces/Time", "nav_msgs/MapMetaData",
    "geometry_msgs/Pose", "geometry_msgs/Point", "geometry_msgs/Quaternion"],
  "nav_msgs/Path": ["std_msgs/Header", "builtin_interfaces/Time", "geometry_msgs/PoseStamped",
    "geometry_msgs/Pose", "geometry_msgs/Point", "geometry_msgs/Quaternion"],
  "sensor_msgs/CompressedImage": ["std_msgs/Header", "builtin_interfaces/Time"],
  "std_msgs/String": [],
  "tf2_msgs/TFMessage": ["geometry_msgs/TransformStamped", "std_msgs/Header", "builtin_interfaces/Time",
    "geometry_msgs/Transform", "geometry_msgs/Vector3", "geometry_msgs/Quaternion"],
};

// schema("nav_msgs/msg/OccupancyGrid") -> the ros2msg text.
export function schema(schemaName) {
  const type = schemaName.replace("/msg/", "/");
  if (!DEPS[type]) throw new Error(`no schema for ${schemaName}`);
  return [DEFS[type], ...DEPS[type].map((d) => `${RULE}\nMSG: ${d}\n${DEFS[d]}`)].join("");
}
