#pragma once

#include <dds/dds.h>
#include <fmt/format.h>

#include <optional>
#include <string>
#include <string_view>

#include "pirouette/robot/ros2/dds_participant.h"
#include "pirouette/robot/ros2/dds_qos.h"
#include "pirouette/robot/ros2/ros2_sample.h"

namespace pirouette::robot::ros2 {

// A DDS reader of ROS 2 message T on topic `relative` of a participant.
// Samples that do not decode as T (truncated, oversized, a wrong type under
// the same name) are dropped by Cyclone's deserialiser and never reach Take.
// Not copyable; deletes its entities. Throws DdsError when Cyclone refuses.
template <class T>
class DdsReader {
 public:
  DdsReader(const DdsParticipant& participant, std::string_view relative, const TopicQos& qos)
      : name_(participant.TopicName(relative)) {
    topic_ = CheckDds(dds_create_topic(participant.entity(), MessageType<T>::Descriptor(),
                                       name_.c_str(), nullptr, nullptr),
                      fmt::format("creating topic {}", name_));
    const QosPointer q = MakeQos(qos);
    reader_ = CheckDds(dds_create_reader(participant.entity(), topic_, q.get(), nullptr),
                       fmt::format("creating a reader of {}", name_));
  }
  ~DdsReader() {
    dds_delete(reader_);
    dds_delete(topic_);
  }
  DdsReader(const DdsReader&) = delete;
  DdsReader& operator=(const DdsReader&) = delete;

  // The oldest sample not yet taken, if any has arrived (valid data only).
  std::optional<Sample<T>> Take() {
    for (;;) {
      Sample<T> sample;
      void* buffer[1] = {&*sample};
      dds_sample_info_t info{};
      const dds_return_t n =
          CheckDds(dds_take(reader_, buffer, &info, 1, 1), fmt::format("taking from {}", name_));
      if (n == 0) return std::nullopt;
      if (info.valid_data) return sample;
    }
  }

  // Waits up to `timeout` for data; true when some has arrived.
  bool WaitForData(dds_duration_t timeout) {
    const dds_entity_t waitset = dds_create_waitset(DDS_CYCLONEDDS_HANDLE);
    const dds_entity_t condition = dds_create_readcondition(reader_, DDS_ANY_STATE);
    dds_waitset_attach(waitset, condition, 0);
    const dds_return_t n = dds_waitset_wait(waitset, nullptr, 0, timeout);
    dds_delete(condition);
    dds_delete(waitset);
    return n > 0;
  }

  int MatchedWriters() const {
    dds_subscription_matched_status_t status{};
    CheckDds(dds_get_subscription_matched_status(reader_, &status),
             fmt::format("reading the matches of {}", name_));
    return static_cast<int>(status.current_count);
  }

  const std::string& topic_name() const { return name_; }

 private:
  std::string name_;
  dds_entity_t topic_ = 0;
  dds_entity_t reader_ = 0;
};

}  // namespace pirouette::robot::ros2
