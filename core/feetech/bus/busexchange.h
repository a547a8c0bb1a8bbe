// The steps every Feetech operation is made of: one exchange, a baud change, a locked write...
#pragma once

#include "bustypes.h"
#include "requestengine.h"

#include <QObject>
#include <QSet>

#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace seriallink {
class LinkSession;
}

namespace feetech {

// One asynchronous step of an operation; it calls `next` once, with what went wrong if not ok.
using StepDone = std::function<void(bool ok, const QString &message)>;
using Step = std::function<void(StepDone next)>;

// One request and what counts as its answer.
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
    // A scan: replyTimeout is the whole wait for an answer's first byte (see Transaction).
    std::optional<std::chrono::microseconds> afterFirstByte;
};
// The reply arrives decoded: the frame the engine accepted is decoded once, on acceptance.
using ExchangeDone = std::function<void(const seriallink::TransactionResult &result,
                                        const std::optional<Packet> &reply)>;

// Why a transaction failed, in words for the user.
QString failureText(const seriallink::TransactionResult &result);
// The same, as the kind of an operation's failure.
OperationFailure failureKind(const seriallink::TransactionResult &result);
// The register `key` of the servo's table; none for an unknown model or a family without it.
const Register *registerAt(const ServoInfo &servo, QStringView key);
// "servo 3 at 1 Mbps"
QString servoName(const ServoInfo &servo);

// The scan, the guided flows, the telemetry cycle and the session all build their work from
// these steps over one link. Lives in the session's thread.
class BusExchange : public QObject
{
    Q_OBJECT

public:
    BusExchange(seriallink::LinkSession &link, const SessionTiming &timing,
                QObject *parent = nullptr);

    seriallink::LinkSession &link() { return m_link; }
    const SessionTiming &timing() const { return m_timing; }

    // How quickly servos answer on this port: the median of the last answers (none before the
    // first), from the end of the request to the first byte of the reply.
    std::optional<std::chrono::microseconds> measuredLatency() const;
    void noteLatency(std::chrono::microseconds latency);
    void forgetLatencies() { m_latencies.clear(); }
    // What a missing ID may cost a scan.
    std::chrono::microseconds scanAllowance() const;

    // An answer that may have the request's very bytes (Transaction::answerMayEqualRequest)
    // is told from the echo here, before `done` hears of it.
    void exchange(const Exchange &exchange, ExchangeDone done);
    // Runs the steps in turn; the first failure ends the run. Nothing is called back once the
    // link has ended or started again in between.
    void runSteps(std::vector<Step> steps, StepDone done);
    // What kind of failure the step that failed last said it was: a step says it with fail(),
    // and None stays when it said only its sentence (its operation knows the kind best then).
    // Cleared as each step of a run starts, so it always speaks of the run's latest step.
    OperationFailure stepFailure() const { return m_stepFailure; }
    // Ends a step as failed, noting its kind for stepFailure().
    void fail(const StepDone &next, OperationFailure kind, const QString &message);

    Step setBaud(qint32 baud);
    Step write(quint8 id, int address, const QByteArray &bytes, bool expectReply,
               const QString &what);
    Step instruction(quint8 id, const QByteArray &request, bool expectReply, const QString &what);
    Step lock(std::shared_ptr<ServoInfo> servo, bool locked);
    // Emits memoryRead with what the servo holds, and hands the bytes to `seen` when given.
    Step read(std::shared_ptr<ServoInfo> servo, int address, int size, ReadSource source,
              std::function<void(const QByteArray &bytes)> seen = {});
    // Reads `blocks` (in address order) in as few READs as the servo takes: blocks a few bytes
    // apart go in one READ, since the unused bytes between them cost less wire time than another
    // request and its turnaround. A servo that does not answer such a READ is read block by
    // block, then and from then on. memoryRead comes once per block either way.
    Step readBlocks(std::shared_ptr<ServoInfo> servo, QVector<Block> blocks, ReadSource source);
    // One read-back READ per key the servo's table has (the others are skipped); `seen` hears
    // each key's value in register units.
    std::vector<Step> readValues(std::shared_ptr<ServoInfo> servo, const QStringList &keys,
                                 std::function<void(const QString &key, qint32 value)> seen);
    // A write of one register by key, in register units; `sending` is called as it goes out
    // (from then on the servo may hold it). Fails at once when the table refuses the value.
    Step writeValue(std::shared_ptr<ServoInfo> servo, const QString &key, qint32 value,
                    std::function<void()> sending);
    Step identify(std::shared_ptr<ServoInfo> servo); // fills in what addresses 0-8 say
    // mustAnswer: fails when the ID is silent; otherwise fails when it answers (ID in use).
    Step ping(quint8 id, bool mustAnswer, int retries);
    // A write of the ID or baud register: its reply may come from the new address or not at
    // all, so only a closed link fails it.
    Step addressWrite(quint8 id, int address, quint8 value, std::optional<quint8> alternateReplyId);
    static Step markDone(std::shared_ptr<bool> flag); // sets the flag when the run gets there
    static Step tolerant(Step step); // the run goes on whether `step` succeeds or not
    // Locks the EEPROM at each place (ID and baud) in turn, whether or not anything answers.
    void relock(std::vector<std::shared_ptr<ServoInfo>> places, std::function<void()> done);
    // Looks for the servo's ID at each rate in turn; on success servo->baud is where it answered.
    void searchBauds(std::shared_ptr<ServoInfo> servo, QVector<qint32> rates, StepDone done);

    // A line of the packet log that is no frame: a servo that stopped answering, say.
    void logNote(const QString &note, bool error = false);

signals:
    // Bytes of one block as the servo holds them, with the status byte of its reply.
    void memoryRead(quint8 id, qint32 baud, int address, const QByteArray &bytes,
                    feetech::ReadSource source, quint8 statusByte);

private:
    // The request got only its own bytes back while the echo was undecided (see exchange()).
    void settleOwnFrame(const Exchange &request, const seriallink::TransactionResult &result,
                        ExchangeDone done);
    // One READ covering `blocks`, handed out block by block; falls back to a READ per block.
    Step readSpan(std::shared_ptr<ServoInfo> servo, QVector<Block> blocks, ReadSource source);

    seriallink::LinkSession &m_link;
    SessionTiming m_timing;
    std::deque<std::chrono::microseconds> m_latencies;
    QSet<qint64> m_refuseLongReads; // servos (baud and ID) read block by block
    OperationFailure m_stepFailure = OperationFailure::None;
};

} // namespace feetech
