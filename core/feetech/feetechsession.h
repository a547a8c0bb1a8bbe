// The Feetech bus session: scan, identify, table reads, safe writes and the guided flows.
#pragma once

#include "feetech/feetechpacket.h"
#include "feetech/registertable.h"
#include "feetech/telemetry.h"
#include "link/linktypes.h"
#include "link/requestengine.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <optional>

namespace seriallink {
class SerialTransport;
}

namespace feetech {

// The longest return delay a servo can be set to: 254 × 2 µs (register 7).
constexpr std::chrono::microseconds kLongestReturnDelay {508};

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

    quint16 modelNumber() const;
    QString firmware() const; // "3.10"
    bool hasTable() const { return model.family.has_value(); }
    // The family's table, or the raw view for an unknown model.
    const RegisterTable &table() const;
    bool repliesToWrites() const { return responseLevel != 0; }
};

// Reads addresses 0-8 as an identity (nothing when the bytes are too few).
std::optional<ServoInfo> servoInfoFromIdentity(quint8 id, qint32 baud, QByteArrayView bytes);

struct TelemetryOptions
{
    QVector<ServoInfo> servos; // in the order their replies are asked for
    double rateHz = 50.0; // samples per second per servo; 0: as fast as the bus allows
    // A servo that misses this many cycles in a row is taken out of the cycle (so it cannot
    // slow the others) and asked alone, once per missingProbeInterval, until it answers.
    int missesBeforeMissing = 3;
    std::chrono::milliseconds missingProbeInterval {1000};
    // servoctl --trace: every frame in the packet log, not only the failures.
    bool logEveryFrame = false;
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
    SyncWrite
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
};

// Lives in a link worker thread (or the CLI's main thread); driven only by signals and timers.
// Operations run one at a time in the order they are asked for; a scan can be cancelled.
class Session : public QObject
{
    Q_OBJECT

public:
    explicit Session(const SessionTiming &timing = {}, QObject *parent = nullptr);
    ~Session() override;

    const seriallink::ConnectionStatus &status() const { return m_status; }
    const seriallink::LinkCounters &counters() const;
    bool isBusy() const { return m_running || !m_queue.empty(); }
    // How quickly servos answer on this port: the median of the last answers (none before the
    // first), from the end of the request to the first byte of the reply.
    std::optional<std::chrono::microseconds> measuredLatency() const;
    std::chrono::microseconds scanAllowance() const;

    // Slots, called through QMetaObject::invokeMethod from other threads.
    void open(const QString &portName, qint32 baud, seriallink::EchoMode echo);
    void close();

    void scan(const feetech::ScanOptions &options);
    void cancelScan();
    void ping(quint8 id, qint32 baud);
    // Every block of the servo's table (the raw view for an unknown model), or only `blocks`.
    // A Refresh is a background read: it runs only when nothing else does.
    void read(const feetech::ServoInfo &servo, const QVector<feetech::Block> &blocks,
              feetech::ReadSource source);
    // EEPROM writes go unlock → write → lock; then every written register is read back.
    // ID and baud changes are refused here: they have their own flows.
    void write(const feetech::ServoInfo &servo, const QVector<feetech::RegisterWrite> &writes);
    void changeId(const feetech::ServoInfo &servo, int newId, const QVector<int> &idsInUse);
    void changeBaud(const feetech::ServoInfo &servo, qint32 newBaud);
    void calibrateMiddle(const feetech::ServoInfo &servo);
    void factoryReset(const feetech::ServoInfo &servo);
    void reboot(const feetech::ServoInfo &servo);
    void clearStatus(const feetech::ServoInfo &servo);

    // Telemetry: a cycle of SYNC READs (one READ per servo where the family has no SYNC READ)
    // of the feedback block, at the options' rate, between operations, until stopTelemetry.
    void startTelemetry(const feetech::TelemetryOptions &options);
    void stopTelemetry();
    bool isStreaming() const { return m_telemetry.has_value(); }
    // Torque enable 0 by broadcast WRITE at each of `bauds`, then read back from `servos`.
    // Runs before anything queued; a running scan is cancelled.
    void torqueOffAll(const QVector<qint32> &bauds, const QVector<feetech::ServoInfo> &servos);
    // One SYNC WRITE (no replies) at `baud`; every entry's data is `length` bytes.
    void syncWrite(qint32 baud, int address, int length,
                   const QVector<feetech::SyncWriteEntry> &entries);

signals:
    void statusChanged(const seriallink::ConnectionStatus &status);
    void scanProgress(int done, int total, qint32 baud);
    void servoFound(const feetech::ServoInfo &servo);
    void scanFinished(bool completed, const QString &message);
    // Bytes of one block as the servo holds them, with the status byte of its reply.
    void memoryRead(quint8 id, qint32 baud, int address, const QByteArray &bytes,
                    feetech::ReadSource source, quint8 statusByte);
    // The status byte of a reply that carried no data (a PING).
    void statusSeen(quint8 id, qint32 baud, quint8 statusByte);
    void progress(int done, int total);
    void operationFinished(const feetech::OperationResult &result);
    void packetLogged(const seriallink::PacketLogEntry &entry);
    void countersChanged(const seriallink::LinkCounters &counters);
    void telemetry(const QVector<feetech::FeedbackSample> &samples, quint64 stream);
    void telemetryStats(const feetech::TelemetryStats &stats);

private:
    using Done = std::function<void(bool ok, const QString &message)>;
    using Step = std::function<void(Done next)>;
    struct Exchange
    {
        QByteArray request;
        std::optional<quint8> replyId; // none: no reply expected
        std::optional<quint8> alternateReplyId; // an ID change may answer from either ID
        int replyDataSize = 0;
        bool listenOnly = false; // wait the whole timeout and accept nothing (broadcast probe)
        bool silenceExpected = false; // scans: no answer is an answer, not a link problem
        // Called with every well-formed frame that is not the answer (a late one, say).
        std::function<void(const Packet &)> otherFrame;
        seriallink::Transaction::Priority priority = seriallink::Transaction::Priority::Command;
        std::optional<std::chrono::microseconds> replyTimeout;
        std::optional<int> retryCount;
    };
    using ExchangeDone = std::function<void(const seriallink::TransactionResult &result,
                                            const std::optional<Packet> &reply)>;

    void setStatus(seriallink::ConnectionState state, const QString &message = {});
    // Ends the running operation and every queued one with `message`, and closes the port.
    void endAll(const QString &message, seriallink::Failure failure);
    void onPortFailed(const QString &message, bool lost);
    void tryReopen();
    void enqueue(Operation operation, std::function<void()> start);
    void finishOperation(const OperationResult &result);
    void startNextOperation();
    void startQueuedOperation(); // the next operation, whether or not a telemetry cycle is due
    void runSteps(std::vector<Step> steps, Done done);

    void exchange(const Exchange &exchange, ExchangeDone done);
    Step stepSetBaud(qint32 baud);
    Step stepWrite(quint8 id, int address, const QByteArray &bytes, bool expectReply,
                   const QString &what);
    Step stepInstruction(quint8 id, const QByteArray &request, bool expectReply,
                         const QString &what);
    Step stepLock(std::shared_ptr<ServoInfo> servo, bool locked);
    Step stepRead(std::shared_ptr<ServoInfo> servo, int address, int size, ReadSource source);
    Step stepIdentify(std::shared_ptr<ServoInfo> servo); // fills in what addresses 0-8 say
    // mustAnswer: fails when the ID is silent; otherwise fails when it answers (ID in use).
    Step stepPing(quint8 id, bool mustAnswer, int retries);
    // A write of the ID or baud register: its reply may come from the new address or not at
    // all, so only a closed link fails it.
    Step stepAddressWrite(quint8 id, int address, quint8 value,
                          std::optional<quint8> alternateReplyId);
    static Step markDone(std::shared_ptr<bool> flag); // sets the flag when the run gets there
    // Locks the EEPROM at each place (ID and baud) in turn, whether or not anything answers.
    void relock(std::vector<std::shared_ptr<ServoInfo>> places, std::function<void()> done);
    void searchBauds(std::shared_ptr<ServoInfo> servo, QVector<qint32> rates, Done done);
    void waitForReboot(const ServoInfo &servo, std::shared_ptr<QElapsedTimer> clock);
    QString servoName(const ServoInfo &servo) const;
    void noteLatency(std::chrono::microseconds latency);

    void scanNext();
    void scanBaud(int baudIndex);
    void probe(int baudIndex, int round);
    void scanId(int baudIndex, int id);
    void recheck(int baudIndex);
    // A scan's PING; the scan ends when the link does, otherwise `then` hears the answer.
    void scanPing(int id, std::optional<std::chrono::microseconds> timeout, int retries,
                  ExchangeDone then);
    void identifyFound(quint8 id, qint32 baud, std::function<void()> then);
    void endScan(bool completed, const QString &message);

    // ---- telemetry (feetechtelemetry.cpp)
    struct TelemetryServo
    {
        ServoInfo info;
        ServoTelemetry stats;
        int missesInARow = 0;
        qint64 nextProbeUs = 0; // when a missing servo is asked again
    };
    struct TelemetryState
    {
        TelemetryOptions options;
        std::vector<TelemetryServo> servos;
        QTimer *timer = nullptr; // the cycle clock; none when running as fast as possible
        bool due = false; // a cycle should start as soon as the bus is free
        bool inCycle = false;
        std::vector<std::function<void(std::function<void()>)>> steps; // of the running cycle
        std::size_t nextStep = 0;
        qint64 startedUs = 0;
        TelemetryStats stats;
        std::deque<std::pair<qint64, qint64>> history; // (time, samples) at each cycle's end
    };
    void telemetryTick();
    bool startTelemetryCycleIfDue(); // true when a cycle started
    void runTelemetryStep();
    void endTelemetryCycle();
    std::function<void(std::function<void()>)> telemetrySyncRead(qint32 baud,
                                                                 QVector<int> servoIndexes);
    std::function<void(std::function<void()>)> telemetryRead(int servoIndex, bool probe);
    void noteTelemetryAnswer(int servoIndex, const Packet &reply, qint64 steadyUs);
    void noteTelemetryMiss(int servoIndex);
    std::chrono::microseconds telemetryAllowance(int servos) const;
    void flushTelemetry();
    void publishTelemetryStats();
    void updateTelemetryStats();
    void logNote(const QString &note, bool error = false);
    // Ends a write queued before the last torque off without sending it; true when it did.
    bool refusedAfterTorqueOff(Operation operation, quint64 epoch);

    SessionTiming m_timing;
    FrameFormat m_format;
    seriallink::SerialTransport *m_transport = nullptr;
    seriallink::RequestEngine *m_engine = nullptr;
    seriallink::ConnectionStatus m_status;
    seriallink::EchoMode m_echo = seriallink::EchoMode::Auto;
    QTimer *m_reopenTimer = nullptr;
    std::deque<std::chrono::microseconds> m_latencies;
    struct Queued
    {
        Operation operation = Operation::Read;
        std::function<void()> start;
    };
    std::deque<Queued> m_queue;
    bool m_running = false;
    Operation m_currentOperation = Operation::Read;
    quint64 m_generation = 0; // callbacks from before a close are ignored

    struct ScanState
    {
        ScanOptions options;
        int baudIndex = 0;
        int done = 0;
        int total = 0;
        int found = 0;
        bool cancelled = false;
        // IDs that answered too late or garbled during the sweep of this rate: asked once more,
        // with time to spare, before the scan moves on.
        QVector<int> recheck;
        QVector<int> foundIds;
    };
    std::optional<ScanState> m_scan;

    std::optional<TelemetryState> m_telemetry;
    quint64 m_torqueOffEpoch = 0; // counts torque-offs: a write queued before one is dropped
    quint64 m_telemetryGeneration = 0; // a new stream or a stop: earlier answers are ignored
    QVector<FeedbackSample> m_telemetryBatch;
    QTimer *m_telemetryFlushTimer = nullptr;
    QTimer *m_telemetryStatsTimer = nullptr;
};

} // namespace feetech

Q_DECLARE_METATYPE(feetech::ServoInfo)
Q_DECLARE_METATYPE(feetech::ScanOptions)
Q_DECLARE_METATYPE(feetech::ReadSource)
Q_DECLARE_METATYPE(feetech::OperationResult)
Q_DECLARE_METATYPE(feetech::RegisterWrite)
Q_DECLARE_METATYPE(feetech::SyncWriteEntry)
Q_DECLARE_METATYPE(feetech::TelemetryOptions)
