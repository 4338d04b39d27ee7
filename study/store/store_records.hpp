#pragma once
// What the writes of both stores (SqliteStore, PostgresStore) share: the texts they store for a
// slot's block order and an onset's detail, and the messages of their refusals, so a study reads
// the same whichever store it runs on.
#include <cstdint>
#include <string>

#include "study/design/counterbalancing.hpp"

namespace tlab::study {

// "block A | block B", the block order of a slot as stored in assignments.block_order.
std::string blockOrderText(const Design& design, const SlotDesign& slot);

// An onset event's detail: `detail` (JSON, or text wrapped as {"detail": ...}) with the showing
// number, and a note when the stimulus is shown again after an interruption.
std::string onsetDetail(const std::string& detail, int showing);

// The refusals both stores give.
std::string enrolledElsewhereMessage(const std::string& location, const std::string& participant);
std::string sessionConflictMessage(const std::string& location, const std::string& participant, std::int64_t session,
                                   const std::string& station, const std::string& startedAt, const std::string& state);
std::string duplicateResponseMessage(const std::string& location, std::int64_t trial);

}  // namespace tlab::study
