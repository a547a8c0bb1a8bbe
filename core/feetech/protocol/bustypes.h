// Value types of a Feetech bus: servo identity, register writes, options, results, timing.
// Plain values with no link behind them, so anything (pages, the CLI, models) may include this.
#pragma once

#include "feetechpacket.h"
#include "modeltable.h"
#include "registertable.h"
#include "requestengine.h"

#include <QByteArrayView>
#include <QMetaType>
#include <QString>
#include <QVariant>
#include <QVector>

#include <chrono>
#include <optional>

namespace feetech {

// Addresses 0-8: firmware, END, model, ID, baud, return delay, response level.
constexpr int kIdentityAddress = 0;
constexpr int kIdentitySize = 9;

// The longest return delay a servo can be set to: 254 × 2 µs (register 7).
constexpr std::chrono::microseconds kLongestReturnDelay {508};

// Where a servo answers: its ID at a baud rate. Two servos of one bus never share both (a
// shared ID is a fault the scan reports), so this names a servo wherever a list index would not.
struct ServoAddress
{
    quint8 id = 0;
    qint32 baud = 0;

    friend bool operator==(const ServoAddress &a, const ServoAddress &b)
    {
        return a.id == b.id && a.baud == b.baud;
    }
    friend bool operator!=(const ServoAddress &a, const ServoAddress &b) { return !(a == b); }
};

inline size_t qHash(const ServoAddress &address, size_t seed = 0)
{
    return ::qHash((quint64(address.id) << 32) | quint32(address.baud), seed);
}

// What a servo says about itself in addresses 0-8 (all single bytes, so byte order plays no
// part in reading them).
struct ServoInfo
{
    quint8 id = 0;
    qint32 baud = 0;
    quint8 firmwareMajor = 0;
    quint8 firmwareMinor = 0;
    quint8 byteOrderFlag = 0; // address 2: 0 little-endian, 1 big-endian
    quint8 modelMajor = 0;
    quint8 modelMinor = 0;
    quint8 baudCode = 0; // address 6
    quint8 responseLevel = 1; // address 8: 0 = only READ and PING answer
    ModelInfo model; // no family: no trusted table, the servo gets the raw view
    quint8 statusBits = 0; // the error bits of its answer to the scan (0x01: voltage)
    // Its feedback reads came back garbled: two or more servos answer at this ID. Nothing is
    // written to it while that is so.
    bool sharedId = false;

    ServoAddress address() const { return {id, baud}; }
    quint16 modelNumber() const;
    QString firmware() const; // "3.10"
    bool hasTable() const { return model.family.has_value(); }
    // The family's table, or the raw view for an unknown model.
    const RegisterTable &table() const;
    bool repliesToWrites() const { return responseLevel != 0; }
};

// Reads addresses 0-8 as an identity (nothing when the bytes are too few).
std::optional<ServoInfo> servoInfoFromIdentity(quint8 id, qint32 baud, QByteArrayView bytes);

// Cycles a servo may miss in a row before a stream takes it out (TelemetryOptions).
constexpr int kDefaultMissesBeforeMissing = 3;

struct TelemetryOptions
{
    QVector<ServoInfo> servos; // in the order their replies are asked for
    double rateHz = 50.0; // samples per second per servo; 0: as fast as the bus allows
    // A servo that misses this many cycles in a row is taken out of the cycle (so it cannot
    // slow the others) and asked alone, once per missingProbeInterval, until it answers.
    int missesBeforeMissing = kDefaultMissesBeforeMissing;
    std::chrono::milliseconds missingProbeInterval {1000};
    // servoctl --trace: every frame in the packet log, not only the failures.
    bool logEveryFrame = false;
    // Each cycle's samples go out as the cycle ends, not batched (a loop that acts on every
    // cycle, such as teleoperation, waits for no batch).
    bool publishEachCycle = false;
    // Names the stream in its samples and statistics, so a client that started a new one can
    // tell late news of the old one apart.
    quint64 stream = 0;
};

enum class MiddleCalibration { Unsupported, TorqueEnable128, Instruction };
// By family and firmware (spec §2.2, §10): 0x0B on STS from 3.10 and on HLS, torque enable 128
// on older STS and on SMS; SCS has no offset register.
MiddleCalibration middleCalibration(const ServoInfo &servo);

struct ScanOptions
{
    int firstId = 0;
    int lastId = kMaxServoId;
    QVector<qint32> bauds {1000000};
    // Every rate starts with a broadcast PING, whose answers (collided or not) measure how fast
    // the line answers. When no byte at all comes back, no servo listens at that rate: it is
    // skipped unless this is off (a thorough scan asks every ID regardless).
    bool skipSilentRates = true;
};

// Where a block of register bytes came from.
enum class ReadSource { Read, Refresh, ReadBack };

struct RegisterWrite
{
    int address = 0;
    QByteArray bytes; // already encoded in the family's byte order
    bool eeprom = false;
};

enum class Operation {
    Scan,
    Ping,
    Read,
    Write,
    ChangeId,
    ChangeBaud,
    CalibrateMiddle,
    FactoryReset,
    Reboot,
    ClearStatus,
    TorqueOff, // every servo of the bus, ahead of the queue
    SyncWrite,
    FindMotor, // motor set-up: the one servo on the bus, at any rate
    SetUpMotor,
    CheckJoints,
    Identify, // a joint's wiggle, with what it changed put back
    HealthCheck, // reads only
    MoveTest, // the health check's confirmed move, with what it changed put back
    Guard, // the guard's hold or torque off, ahead of the queue; reported as a GuardEvent
    RecoverOverload, // torque off and on again after an overload trip, then the status checked
    LockEeprom, // the EEPROM lock closed and read back (a lock left open)
    SendPacket, // a frame built by hand (the packet window), sent once as it is
    CheckSharedId, // reads only: whether several servos answer at one ID
    CheckSettings, // reads only: the settings check's reads of each servo
    FixSettings, // the settings check's fixes of one servo, each read back
    Replay // a recorded motion played on several servos, eased in, held at the end
};

// Why an operation that ran (or was due to run) on the bus did not succeed: stable, so callers
// and tests branch on it rather than on OperationResult::message, the sentence for the user.
enum class OperationFailure {
    None,
    NotConnected, // the port was closed when its turn came
    LinkLost, // the link went down while it ran or waited, or the port closed under it
    // All torque off was asked for after it was submitted: not sent, or stopped where it was
    AfterTorqueOff,
    PortSetting, // the port could not be set to the servo's baud rate
    NoAnswer, // a servo stayed silent after every attempt
    BadReply, // an answer came, but says nothing usable (too short, a value beyond decoding)
    NotVerified, // what was read back differs from what was written or asked for
    IdInUse, // the new ID (or the ID at the new rate) already answers
    Unsupported, // the servo's model or its mode cannot do it, or the model is unknown
    InvalidRequest, // asked for what cannot be: an ID or rate out of range, a value refused
    NothingToDo, // the servo already is as asked, or nothing was asked for
    Stopped, // stopped by the user or cancelled before it ended
    GuardStopped, // the overload guard stopped the move
    NoRoomToMove, // the servo stands where its limits leave no room for the move
    StillLatched, // the overload bit stayed set: only a power cycle clears it
    SharedId, // several servos answer at the ID
    SeveralServos, // more than the one servo a motor set-up needs answers
    WrongModel, // the one servo found is not of the model asked for
    // The bus is shared with another program, and the operation would change the port's rate
    // under it (a scan, a new baud rate, a motor set-up, a factory reset)
    BusShared,
};

struct OperationResult
{
    Operation operation = Operation::Read;
    bool ok = false;
    QString message; // for the user; says what went wrong when !ok
    ServoInfo servo; // as the servo is reached after the operation (new ID or baud)
    std::chrono::microseconds latency {0}; // Ping: the measured answer time
    // Set by BusClient: a control write (torque, goal, a move of all servos), which pages
    // report in place rather than as a change of the servo list.
    bool control = false;
    // False for a step of an apply chain that more steps follow (the operation goes on).
    bool final = true;
    // A Write that failed after its frames went out: they may have landed. What its read-backs
    // did not settle is reported as unknown, not as unwritten.
    bool writesSent = false;
    // None when ok. LinkLost: ended by the link going down (running, paused or still queued),
    // not by the servo; whoever watches the connection reports that once. StillLatched
    // (RecoverOverload): only a power cycle clears the overload bit.
    OperationFailure failure = OperationFailure::None;
    // The submission it answers (BusOperation::ticket), which BusClient turns into its reply;
    // 0 where nobody asked for one (the guard, servoctl).
    quint64 ticket = 0;
    // What the operation found besides ok and message, when it has more to say: a
    // MotorSetupResult (FindMotor, SetUpMotor), a QVector<JointCheck> (CheckJoints), a
    // MoveTestResult (MoveTest). Empty when it ended before it could say (a lost link).
    QVariant detail {};
};

// How far a running operation has got: `done` of `total` (an apply chain's writes, a health
// check's servos, a motor set-up's steps), with a sentence where it has one, and what it just
// found (a HealthReading for each servo of a health check).
struct OperationProgress
{
    quint64 ticket = 0; // as in OperationResult
    int done = 0;
    int total = 0;
    QString text;
    QVariant detail {};
};

struct SessionTiming
{
    seriallink::EngineTiming engine {std::chrono::milliseconds(20), 2, std::chrono::milliseconds(1),
                                     false};
    // Scan: what a missing ID may cost before any answer has been measured on this port.
    std::chrono::microseconds initialScanAllowance {20000};
    // The broadcast probe decides whether a whole baud rate is skipped: it waits generously.
    std::chrono::microseconds probeAllowance {50000};
    // Once answers are measured: this many times the slowest one, plus the longest return
    // delay a servo can be set to (254 × 2 µs), within these bounds.
    double scanLatencyFactor = 3.0;
    std::chrono::microseconds minimumScanAllowance {1500};
    std::chrono::microseconds maximumScanAllowance {60000};
    // Telemetry waits like a scan (the measured answer time, plus a return delay for every
    // servo of a SYNC READ), but never less than this: a sample that comes late would
    // otherwise be taken for the next cycle's.
    std::chrono::microseconds minimumTelemetryAllowance {3000};
    // Samples reach the GUI in batches, at most this often.
    std::chrono::milliseconds telemetryBatchInterval {20};
    std::chrono::milliseconds telemetryStatsInterval {250};
    // After a reboot: how long to keep asking before the servo counts as gone.
    std::chrono::milliseconds rebootGiveUp {4000};
    std::chrono::milliseconds rebootPollInterval {100};
    std::chrono::milliseconds reconnectInterval {500};
    // Identify: how often the horn's position is read while it moves, and how long one move
    // may take before the wiggle goes on without it (a joint held by a load).
    std::chrono::milliseconds identifyPollInterval {40};
    std::chrono::milliseconds identifyMoveTimeout {2500};
};

} // namespace feetech

Q_DECLARE_METATYPE(feetech::ServoInfo)
Q_DECLARE_METATYPE(feetech::ScanOptions)
Q_DECLARE_METATYPE(feetech::ReadSource)
Q_DECLARE_METATYPE(feetech::OperationResult)
Q_DECLARE_METATYPE(feetech::OperationProgress)
Q_DECLARE_METATYPE(feetech::RegisterWrite)
Q_DECLARE_METATYPE(feetech::SyncWriteEntry)
Q_DECLARE_METATYPE(feetech::TelemetryOptions)
