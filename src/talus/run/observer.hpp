#pragma once
// What the run loop calls at output times, for every method alike. An
// observer holds a reference to the state it reads (a DEM system, an MPM
// solver, a runout model), so the calls carry nothing: the loop knows no
// method's types.
namespace talus::run {

class Observer {
 public:
  virtual ~Observer() = default;
  virtual void on_series() {}
  virtual void on_snapshot() {}
  // After this time's series row and snapshot: flush what a resumed run reads
  // back; the method's own outputs write checkpoint.bin.
  virtual void on_checkpoint() {}
  // Every second or so of wall time: flush what a user may follow live.
  virtual void on_progress() {}
};

}  // namespace talus::run
