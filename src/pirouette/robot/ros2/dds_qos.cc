#include "pirouette/robot/ros2/dds_qos.h"

namespace pirouette::robot::ros2 {

QosPointer MakeQos(const TopicQos& qos) {
  QosPointer result(dds_create_qos(), &dds_delete_qos);
  constexpr dds_duration_t kMaxBlocking = DDS_MSECS(100);
  dds_qset_reliability(result.get(),
                       qos.reliable ? DDS_RELIABILITY_RELIABLE : DDS_RELIABILITY_BEST_EFFORT,
                       kMaxBlocking);
  dds_qset_durability(
      result.get(), qos.transient_local ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  dds_qset_history(result.get(), DDS_HISTORY_KEEP_LAST, qos.depth);
  if (qos.ignore_local) dds_qset_ignorelocal(result.get(), DDS_IGNORELOCAL_PROCESS);
  return result;
}

}  // namespace pirouette::robot::ros2
