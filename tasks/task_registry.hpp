#pragma once
// The tasks by name — the names used everywhere (CLI, experiment files, database):
// layer-index, follow-boundary, nearest-point, counting, target-discovery, pattern.
#include <memory>
#include <string>
#include <vector>

#include "tasks/task.hpp"

namespace tlab::tasks {

std::vector<std::string> taskNames();
// Throws std::invalid_argument listing the known names.
std::unique_ptr<Task> makeTask(const std::string& name);

}  // namespace tlab::tasks
