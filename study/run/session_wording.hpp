#pragma once
// What the session flow tells participants about the trials ahead, in words every front end
// (window, browser) shows alike, in the experiment's language (ParticipantTexts): how many trials
// a task has and its time limit (with the task's instructions), and how many trials or blocks are
// left at a break.
#include <cstddef>
#include <string>

#include "study/design/experiment.hpp"
#include "study/design/session_plan.hpp"
#include "tasks/answer_parser.hpp"
#include "tasks/question.hpp"

namespace tlab::study {

// "3 trials" / "1 trial": a count with its noun in the right number (the admin page's English).
std::string countOf(long n, const std::string& singular, const std::string& plural);

// A time limit in words: "45 seconds", "1 minute", "2.5 minutes" ("2,5 Minuten").
std::string durationText(double seconds, const ParticipantTexts& texts);

// The task's instructions followed by how many trials of it come now (the run of trials of the
// same task and phase from `index` on) and their time limit.
std::string taskIntroduction(const SessionPlan& plan, std::size_t index, const std::string& instructions, const ParticipantTexts& texts);

// The break's text followed by what is left after trial `done`: test trials, or blocks when the
// breaks count blocks.
std::string breakText(const SessionPlan& plan, std::size_t done, const BreakSpec& spec, const ParticipantTexts& texts);

// A trial's question in the participant's language: the question's text key formatted with its
// arguments (the [question] table), or its English text when the task gave no key.
std::string questionWording(const tasks::Question& question, const ParticipantTexts& texts);

// Why a typed answer was refused, in the participant's language when the refusal names a key of
// the [refusal] table; its English message (without the "answer: " prefix) otherwise.
std::string refusalWording(const tasks::AnswerFormatError& refusal, const ParticipantTexts& texts);

}  // namespace tlab::study
