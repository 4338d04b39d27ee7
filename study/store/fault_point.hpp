#pragma once
// Fault points for the crash-safety tests (after SQLite's testing culture): a test names one point
// in the environment variable TLAB_STOP_AT ("open", "prepare:3", "session", "commit:2", "ack:5");
// when the process reaches it, it prints one line on stderr and stops itself with SIGSTOP, so the
// test can SIGKILL it at exactly that point instead of at a moment a timer hopes to hit. Without
// the variable a fault point does nothing. The points and what they mean:
//   open        the study database is open, nothing of this run is written yet
//   prepare:N   the N-th stimulus of this process has been prepared (rendered or read back)
//   session:N   the N-th session of this process has started (its row is committed)
//   onset:N     the N-th stimulus onset of this process is committed, the response is not
//   commit:N    inside the N-th response transaction, after its inserts, before COMMIT
//   ack:N       the N-th response of this process is committed and acknowledged
//   feedback:N  the N-th training feedback screen is on screen (window)
//   break:N     the N-th break screen is on screen (window)
#include <string_view>

namespace tlab::study {

// Stops the process when TLAB_STOP_AT equals `name` (count 0) or "name:count".
void faultPoint(std::string_view name, int count = 0);

}  // namespace tlab::study
