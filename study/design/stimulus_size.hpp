#pragma once
// A run at another stimulus size than the experiment file's (`tlab simulate --size`, `tlab demo
// --size`): the size is changed in the experiment's text too, so the text stored with the data
// says which size the stimuli had (and is a version of its own).
#include <string>

#include "study/design/experiment.hpp"

namespace tlab::study {

// The experiment text with [stimulus] size = "WxH": the size line replaced where the table has
// one, else added below the [stimulus] header, else a [stimulus] table appended at the end.
std::string withStimulusSize(const std::string& experimentText, const std::string& size);

// `experiment` (already read and checked) at the stimulus size `size` ("WxH"): its text rewritten
// and parsed again, so the size is checked as the file's own would be.
Experiment withStimulusSize(const Experiment& experiment, const std::string& size);

}  // namespace tlab::study
