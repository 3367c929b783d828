#pragma once
// Loggers that write each sensor's sample when it arrives, stamped with the
// sensor's own clock (SeaExplorer payload files), or that log a state change
// as two records at one instant (Seaglider gc_state: the state left and the
// state entered), write rows whose times are not strictly increasing by
// design. These functions put such rows in order before the common time-order
// repair (time_order.h), which would otherwise report every one of them as a
// damaged row.
#include "missionlog/log_table.h"
#include "missionlog/read_report.h"

namespace auv::detail {

// Sorts the rows by time (stable) when every step back is shorter than
// `maxBackStep_s`: arrival-order jitter. A larger step back is a clock jump
// and is left for repairTimeOrder to report. Times must be finite. Returns
// true when the rows were sorted.
bool sortArrivalJitter(LogTable& table, double maxBackStep_s);

enum class SameTimeRows {
  kMergeUnlessConflict,  // samples of different sensors at one instant: one row
  kLaterWins,            // a state change: the state entered is what holds from then on
};

// Merges neighbouring rows with exactly the same time into one (counted in
// report.rows_merged, not noted as a problem). kMergeUnlessConflict leaves a
// pair whose cells disagree for repairTimeOrder to report.
void mergeSameTimeRows(LogTable& table, SameTimeRows rule, ReadReport& report);

}  // namespace auv::detail
