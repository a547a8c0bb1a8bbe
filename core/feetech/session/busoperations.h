// The operations a Feetech bus session runs, each made as a BusOperation to submit
// (Session::submit, BusClient::submit): reads, writes and apply chains, the guided flows, All
// torque off, motor set-up, identify, the health check, motion replay and hand-built packets.
#pragma once

#include "applyflow.h"
#include "busoperation.h"
#include "bustypes.h"
#include "motionreplay.h"
#include "motorsetup.h"
#include "settingscheck.h"

#include <optional>

namespace feetech::operations {

BusOperation scan(const ScanOptions &options);
BusOperation ping(quint8 id, qint32 baud);
// Whether several servos answer at the servo's ID (sharedidcheck.h): ok with servo.sharedId
// set, or not ok when the reads went unanswered.
BusOperation checkSharedId(const ServoInfo &servo);
// Every block of the servo's table (the raw view for an unknown model), or only `blocks`.
BusOperation read(const ServoInfo &servo, const QVector<Block> &blocks, ReadSource source);
// EEPROM writes go unlock → write → lock; then every written register is read back. ID and
// baud changes are refused here: they have their own flows.
BusOperation write(const ServoInfo &servo, const QVector<RegisterWrite> &writes);
// Everything pending, planned by planApply: the registers, then the ID, then the baud rate,
// each only once the one before succeeded. Every step reports its own result; all but the last
// have `final` unset.
BusOperation apply(const ServoInfo &servo, const ApplyPlan &plan);
BusOperation changeId(const ServoInfo &servo, int newId, const QVector<int> &idsInUse);
BusOperation changeBaud(const ServoInfo &servo, qint32 newBaud);
BusOperation calibrateMiddle(const ServoInfo &servo);
BusOperation factoryReset(const ServoInfo &servo);
BusOperation reboot(const ServoInfo &servo);
BusOperation clearStatus(const ServoInfo &servo);
// Closes the servo's EEPROM lock (one left open by a write cut short) and reads it back: ok
// only when it reads back locked.
BusOperation lockEeprom(const ServoInfo &servo);
// A frame built by hand, sent once at `baud`: it waits for the answer of `replyId`
// (`replyDataSize` data bytes), or, without one, listens for a while; what comes back is in the
// packet log.
BusOperation sendPacket(const QByteArray &frame, qint32 baud, std::optional<quint8> replyId,
                        int replyDataSize);
// A small, slow, torque-limited wiggle around where the servo stands, then everything it
// changed put back (see JointIdentify). Between its moves the bus is free for telemetry and All
// torque off, which stops it with the torque left off. Session::cancel stops it.
BusOperation identifyJoint(const ServoInfo &servo);
// Torque enable 0 by broadcast WRITE at each of `bauds`, then read back from `servos`. Ahead of
// everything queued; a running scan is cancelled.
BusOperation torqueOffAll(const QVector<qint32> &bauds, const QVector<ServoInfo> &servos);
// One SYNC WRITE (no replies) at `baud`; every entry's data is `length` bytes.
BusOperation syncWrite(qint32 baud, int address, int length,
                       const QVector<SyncWriteEntry> &entries);
// Torque off and on again, then the status checked (see recoverOverload in
// overloadrecovery.h); with `checkOnly` (after a power cycle) only the status. The result's
// failure StillLatched says a power cycle is needed.
BusOperation recoverOverload(const ServoInfo &servo, bool checkOnly);
// Motor set-up (MotorSetup): the one servo on the bus found at any rate; found and set up as
// `target` says (the result's detail is the MotorSetupResult); the joints that already answer
// at their ID at `baud` (the detail is the QVector<JointCheck>).
BusOperation findMotor(const MotorTarget &target);
BusOperation setUpMotor(const MotorTarget &target);
BusOperation checkJoints(qint32 baud, const QVector<JointCheck> &joints);
// Reads only. Each servo in turn gets its limits and `reads` feedback blocks read (HealthCheck);
// each reading comes as progress (its detail the HealthReading), and the bus is free for All
// torque off and telemetry between two servos.
BusOperation checkHealth(const QVector<ServoInfo> &servos, int reads);
// The move test (HealthMoveTest; the result's detail is the MoveTestResult): the caller submits
// it only once the user confirmed it.
BusOperation moveTest(const ServoInfo &servo);
// Reads only. Each servo in turn gets its settings read (readSettings in settingsbus.h, with
// `keys` beyond what the rules read); each reading comes as progress (its detail the
// SettingsReading), and the bus is free for All torque off and telemetry between two servos.
BusOperation checkSettings(const QVector<ServoInfo> &servos, const QStringList &keys);
// The fixes of `findings`, servo by servo (fixSettings in settingsbus.h); the result's detail is
// the QVector<SettingsFixOutcome>, one per finding in their order. ok when every one verified.
BusOperation fixSettings(const QVector<SettingsFinding> &findings);
// A recorded motion (MotionReplay): checked against the servos' angle limits before anything
// moves, torque on without a jump, eased in, played at the recorded times by SYNC WRITE, held
// or released at the end. Each goal sent comes as progress (its detail a ReplayPosition); the
// bus is free for telemetry and All torque off between two. Session::cancel stops it with the
// servos held where they stand.
BusOperation replayMotion(const ReplayPlan &plan);

} // namespace feetech::operations
