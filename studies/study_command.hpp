#pragma once
// The `study` verb: the studies' list and the dispatch to each (see each study's header).
#include "studies/study_options.hpp"

namespace lbdem::studies {

/// Runs the named study's cases one after another, then compares them.
int run_study(const StudyOptions& opt);

}  // namespace lbdem::studies
