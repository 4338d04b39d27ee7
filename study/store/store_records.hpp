#pragma once
// What both stores (SqliteStore, PostgresStore) share around their statements: finding a version
// by its text, the texts they store for a slot's block order and an onset's detail, and the
// messages of their refusals, so a study reads the same whichever store it runs on.
#include <cstdint>
#include <string>

#include "study/design/counterbalancing.hpp"
#include "study/store/store.hpp"

namespace tlab::study {

// The version among `versions` whose file text is `text` (by sha256), if any.
std::optional<ExperimentVersion> versionWithText(const std::vector<ExperimentVersion>& versions, const std::string& text);
// The row of the newest of `versions` (oldest first), if any.
std::optional<std::int64_t> newestVersionRow(const std::vector<ExperimentVersion>& versions);

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
