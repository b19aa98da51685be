#include "pirouette/robot/ros2/ros2_cdr.h"

#include <gtest/gtest.h>

#include <vector>

#include "pirouette/robot/ros2/ros2_msg_schema.h"
#include "pirouette/robot/ros2/ros2_sample.h"

namespace pirouette::robot::ros2 {
namespace {

TEST(Ros2CdrTest, StringIsLittleEndianPlainCdrAfterItsHeader) {
  Sample<std_msgs_msg_dds__String_> message;
  SetString(message->data, "ab");
  // Header CDR_LE, then the length with its NUL (3) and the bytes.
  const std::vector<std::uint8_t> expected = {0, 1, 0, 0, 3, 0, 0, 0, 'a', 'b', 0};
  EXPECT_EQ(SerializeCdr(*message), expected);
}

TEST(Ros2CdrTest, AlignmentCountsFromAfterTheHeader) {
  // Time (int32, uint32) then a string, then a float32 and two uint32s, then
  // doubles: an OccupancyGrid's info.origin lands on an 8-byte boundary of the
  // body, 4 bytes past one of the whole buffer.
  Sample<nav_msgs_msg_dds__OccupancyGrid_> grid;
  SetString(grid->header.frame_id, "map");  // 4 + 4 + (4 + 4) = 16 bytes
  grid->info.resolution = 0.05F;
  grid->info.width = 2;
  grid->info.height = 1;
  grid->info.origin.position.x = 1.5;
  const std::vector<std::int8_t> cells = {0, -1};
  SetSequence(grid->data, std::span<const std::int8_t>(cells));
  const std::vector<std::uint8_t> bytes = SerializeCdr(*grid);
  // body: stamp 8, frame_id 8, map_load_time 8, resolution, width, height 12,
  // padding 4 to 40, position 24, orientation 32, data count 4 and 2 bytes.
  ASSERT_EQ(bytes.size(), 4U + 40U + 24U + 32U + 4U + 2U);
  double x = 0.0;
  std::memcpy(&x, bytes.data() + 4 + 40, sizeof x);
  EXPECT_EQ(x, 1.5);
}

TEST(Ros2CdrTest, RoundTripsAPath) {
  Sample<nav_msgs_msg_dds__Path_> path;
  SetString(path->header.frame_id, "map");
  ResizeSequence(path->poses, 3);
  for (std::uint32_t i = 0; i < 3; ++i) {
    SetString(path->poses._buffer[i].header.frame_id, "map");
    SetPose(path->poses._buffer[i].pose, core::Pose2(i, 2.0 * i, 0.1 * i));
  }
  const std::vector<std::uint8_t> bytes = SerializeCdr(*path);
  Sample<nav_msgs_msg_dds__Path_> back;
  ASSERT_TRUE(DeserializeCdr(bytes, *MessageType<nav_msgs_msg_dds__Path_>::Descriptor(), &*back));
  ASSERT_EQ(back->poses._length, 3U);
  EXPECT_STREQ(back->header.frame_id, "map");
  EXPECT_DOUBLE_EQ(back->poses._buffer[2].pose.position.y, 4.0);
  EXPECT_EQ(SerializeCdr(*back), bytes);
}

TEST(Ros2CdrTest, RefusesTruncatedOrForeignBytes) {
  Sample<std_msgs_msg_dds__String_> message;
  SetString(message->data, "hello");
  std::vector<std::uint8_t> bytes = SerializeCdr(*message);
  const auto* type = MessageType<std_msgs_msg_dds__String_>::Descriptor();
  Sample<std_msgs_msg_dds__String_> back;
  EXPECT_FALSE(DeserializeCdr(std::span(bytes).first(bytes.size() - 3), *type, &*back));
  EXPECT_FALSE(DeserializeCdr(std::span(bytes).first(2), *type, &*back));
  bytes[1] = 0;  // CDR_BE
  EXPECT_FALSE(DeserializeCdr(bytes, *type, &*back));
}

TEST(Ros2MsgSchemaTest, WritesTheTypeThenEachDependencyOnce) {
  const std::optional<std::string> schema = Ros2MsgSchema("nav_msgs/msg/Path");
  ASSERT_TRUE(schema.has_value());
  EXPECT_EQ(schema->rfind("std_msgs/Header header\ngeometry_msgs/PoseStamped[] poses\n", 0), 0U);
  const std::string rule = std::string(80, '=') + "\nMSG: std_msgs/Header\n";
  ASSERT_NE(schema->find(rule), std::string::npos);
  EXPECT_EQ(schema->find(rule, schema->find(rule) + 1), std::string::npos);
  EXPECT_NE(schema->find("MSG: builtin_interfaces/Time\nint32 sec\nuint32 nanosec\n"),
            std::string::npos);
  EXPECT_NE(schema->find("MSG: geometry_msgs/Quaternion\n"), std::string::npos);
  EXPECT_FALSE(Ros2MsgSchema("nav_msgs/msg/Nothing").has_value());
  EXPECT_FALSE(Ros2MsgSchema("nonsense").has_value());
}

TEST(Ros2MsgSchemaTest, KnowsEveryPublishedType) {
  for (const char* type :
       {"nav_msgs/msg/OccupancyGrid", "tf2_msgs/msg/TFMessage", "nav_msgs/msg/Path",
        "sensor_msgs/msg/CompressedImage", "sensor_msgs/msg/Image", "std_msgs/msg/String"}) {
    EXPECT_TRUE(Ros2MsgSchema(type).has_value()) << type;
  }
}

}  // namespace
}  // namespace pirouette::robot::ros2
