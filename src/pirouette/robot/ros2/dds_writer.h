#pragma once

#include <dds/dds.h>
#include <fmt/format.h>

#include <string>
#include <string_view>

#include "pirouette/robot/ros2/dds_participant.h"
#include "pirouette/robot/ros2/dds_qos.h"
#include "pirouette/robot/ros2/ros2_message_type.h"

namespace pirouette::robot::ros2 {

// A DDS writer of ROS 2 message T on topic `relative` of a participant (its
// namespace applied: DdsParticipant::TopicName). Not copyable; deletes its
// entities. Throws DdsError when Cyclone refuses the topic or the writer.
template <class T>
class DdsWriter {
 public:
  DdsWriter(const DdsParticipant& participant, std::string_view relative, const TopicQos& qos)
      : name_(participant.TopicName(relative)) {
    topic_ = CheckDds(dds_create_topic(participant.entity(), MessageType<T>::Descriptor(),
                                       name_.c_str(), nullptr, nullptr),
                      fmt::format("creating topic {}", name_));
    const QosPointer q = MakeQos(qos);
    writer_ = CheckDds(dds_create_writer(participant.entity(), topic_, q.get(), nullptr),
                       fmt::format("creating a writer of {}", name_));
  }
  ~DdsWriter() {
    dds_delete(writer_);
    dds_delete(topic_);
  }
  DdsWriter(const DdsWriter&) = delete;
  DdsWriter& operator=(const DdsWriter&) = delete;

  // Sends one message (serialised at once: `message` may change after).
  void Write(const T& message) {
    CheckDds(dds_write(writer_, &message), fmt::format("writing {}", name_));
  }

  // How many readers the writer has matched (discovery may take a moment).
  int MatchedReaders() const {
    dds_publication_matched_status_t status{};
    CheckDds(dds_get_publication_matched_status(writer_, &status),
             fmt::format("reading the matches of {}", name_));
    return static_cast<int>(status.current_count);
  }

  const std::string& topic_name() const { return name_; }
  dds_entity_t entity() const { return writer_; }

 private:
  std::string name_;
  dds_entity_t topic_ = 0;
  dds_entity_t writer_ = 0;
};

}  // namespace pirouette::robot::ros2
