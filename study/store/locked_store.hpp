#pragma once
// LockedStore: one Store shared by many threads (the session threads of `tlab serve`), each call
// made under one mutex. A Store's calls are whole transactions, so serialising them keeps every
// guarantee of the store (one transaction per response, an onset before it) while the server's
// threads take turns; SQLite allows one writer at a time anyway.
#include <memory>
#include <mutex>

#include "study/store/store.hpp"

namespace tlab::study {

class LockedStore : public Store {
 public:
  explicit LockedStore(std::unique_ptr<Store> store) : owner_(std::move(store)), store_(*owner_) {}

  const std::string& location() const override { return store_.location(); }
  std::vector<std::string> experimentIds() override {
    const std::lock_guard lock(mutex_);
    return store_.experimentIds();
  }
  std::vector<ExperimentVersion> versions(const std::string& experimentId) override {
    const std::lock_guard lock(mutex_);
    return store_.versions(experimentId);
  }
  std::optional<ExperimentVersion> findVersion(const Experiment& experiment) override {
    const std::lock_guard lock(mutex_);
    return store_.findVersion(experiment);
  }
  std::optional<std::int64_t> findExperiment(const std::string& experimentId) override {
    const std::lock_guard lock(mutex_);
    return store_.findExperiment(experimentId);
  }
  int sessionCount(std::int64_t versionRow) override {
    const std::lock_guard lock(mutex_);
    return store_.sessionCount(versionRow);
  }
  std::optional<ParticipantRecord> findParticipant(const std::string& experimentId, const std::string& participant) override {
    const std::lock_guard lock(mutex_);
    return store_.findParticipant(experimentId, participant);
  }
  int nextFreeSlot(const std::string& experimentId) override {
    const std::lock_guard lock(mutex_);
    return store_.nextFreeSlot(experimentId);
  }
  std::optional<ParticipantRecord> enrol(const Experiment& experiment, const std::string& tlabVersion, const std::string& participant, int slot, const Design& design, const std::vector<TrialRecord>& trials) override {
    const std::lock_guard lock(mutex_);
    return store_.enrol(experiment, tlabVersion, participant, slot, design, trials);
  }
  void dropParticipant(const std::string& experimentId, const std::string& participant, const std::string& reason) override {
    const std::lock_guard lock(mutex_);
    store_.dropParticipant(experimentId, participant, reason);
  }
  void finishParticipant(std::int64_t participantId) override {
    const std::lock_guard lock(mutex_);
    store_.finishParticipant(participantId);
  }
  std::vector<AssignmentRecord> assignments(const std::string& experimentId) override {
    const std::lock_guard lock(mutex_);
    return store_.assignments(experimentId);
  }
  std::int64_t startSession(std::int64_t participantId, const Experiment& experiment, const std::string& tlabVersion, const std::string& mode) override {
    const std::lock_guard lock(mutex_);
    return store_.startSession(participantId, experiment, tlabVersion, mode);
  }
  void endSession(std::int64_t session, const std::string& reason) override {
    const std::lock_guard lock(mutex_);
    store_.endSession(session, reason);
  }
  void insertTrials(std::int64_t participantId, const std::vector<TrialRecord>& trials) override {
    const std::lock_guard lock(mutex_);
    store_.insertTrials(participantId, trials);
  }
  std::vector<TrialRecord> trials(std::int64_t participantId) override {
    const std::lock_guard lock(mutex_);
    return store_.trials(participantId);
  }
  std::map<std::string, double> usedSeconds(std::int64_t participantId) override {
    const std::lock_guard lock(mutex_);
    return store_.usedSeconds(participantId);
  }
  int recordOnset(std::int64_t session, std::int64_t trial, std::int64_t tNs, const std::string& detail) override {
    const std::lock_guard lock(mutex_);
    return store_.recordOnset(session, trial, tNs, detail);
  }
  void recordResponse(const ResponseRecord& response) override {
    const std::lock_guard lock(mutex_);
    store_.recordResponse(response);
  }
  void recordEvent(std::int64_t session, std::optional<std::int64_t> trial, std::int64_t tNs, const std::string& kind, const std::string& detail) override {
    const std::lock_guard lock(mutex_);
    store_.recordEvent(session, trial, tNs, kind, detail);
  }
  void recordEvents(std::int64_t session, std::optional<std::int64_t> trial, const std::vector<EventRecord>& events) override {
    const std::lock_guard lock(mutex_);
    store_.recordEvents(session, trial, events);
  }
  void recordQuestionnaire(std::int64_t participantId, std::int64_t session, const std::string& questionnaire, int block, const std::vector<FormAnswer>& answers) override {
    const std::lock_guard lock(mutex_);
    store_.recordQuestionnaire(participantId, session, questionnaire, block, answers);
  }
  bool hasQuestionnaireAnswers(std::int64_t participantId, const std::string& questionnaire, int block) override {
    const std::lock_guard lock(mutex_);
    return store_.hasQuestionnaireAnswers(participantId, questionnaire, block);
  }
  void recordDecline(const Experiment& experiment, const std::string& tlabVersion, const std::string& participant) override {
    const std::lock_guard lock(mutex_);
    store_.recordDecline(experiment, tlabVersion, participant);
  }
  void recordConsent(std::int64_t participantId, std::int64_t session, bool accepted) override {
    const std::lock_guard lock(mutex_);
    store_.recordConsent(participantId, session, accepted);
  }
  bool hasConsent(std::int64_t participantId) override {
    const std::lock_guard lock(mutex_);
    return store_.hasConsent(participantId);
  }
  std::optional<std::string> lastEventDetail(std::int64_t participantId, const std::string& kind) override {
    const std::lock_guard lock(mutex_);
    return store_.lastEventDetail(participantId, kind);
  }
  void recordInfo(std::int64_t participantId, std::int64_t session, const std::vector<FormAnswer>& answers) override {
    const std::lock_guard lock(mutex_);
    store_.recordInfo(participantId, session, answers);
  }
  bool hasInfo(std::int64_t participantId) override {
    const std::lock_guard lock(mutex_);
    return store_.hasInfo(participantId);
  }
  void recordDisplay(std::int64_t session, const std::string& displayJson) override {
    const std::lock_guard lock(mutex_);
    store_.recordDisplay(session, displayJson);
  }
  DataTable exportTable(ExportTable table, const Experiment& experiment) override {
    const std::lock_guard lock(mutex_);
    return store_.exportTable(table, experiment);
  }
  std::vector<AnalysisRecord> analysisRecords(const std::string& experimentId, const std::string& dependentVariable) override {
    const std::lock_guard lock(mutex_);
    return store_.analysisRecords(experimentId, dependentVariable);
  }
  std::vector<std::map<std::string, int>> sessionModes(const std::string& experimentId) override {
    const std::lock_guard lock(mutex_);
    return store_.sessionModes(experimentId);
  }
  std::vector<StoredAnswer> formAnswers(const std::string& experimentId) override {
    const std::lock_guard lock(mutex_);
    return store_.formAnswers(experimentId);
  }
  DataTable stimulusSummary(const std::string& experimentId) override {
    const std::lock_guard lock(mutex_);
    return store_.stimulusSummary(experimentId);
  }
  DataTable stimulusExamples(const std::string& experimentId) override {
    const std::lock_guard lock(mutex_);
    return store_.stimulusExamples(experimentId);
  }
  DataTable liveTrials(const std::string& experimentId) override {
    const std::lock_guard lock(mutex_);
    return store_.liveTrials(experimentId);
  }
  DataTable trialFrames(std::int64_t trial) override {
    const std::lock_guard lock(mutex_);
    return store_.trialFrames(trial);
  }

 private:
  std::unique_ptr<Store> owner_;
  Store& store_;
  std::mutex mutex_;
};

}  // namespace tlab::study
