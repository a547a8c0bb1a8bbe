// The shared-ID check: a few reads of the feedback block, a majority decides.
#include "sharedidcheck.h"

#include "feetechpacket.h"

#include <QCoreApplication>

namespace {

struct SharedIdCheckTr
{
    Q_DECLARE_TR_FUNCTIONS(SharedIdCheck)
};

} // namespace

namespace feetech {

namespace {

constexpr int kMajority = kSharedIdReads / 2 + 1;

struct Tally
{
    int clean = 0;
    int garbled = 0;
    int silent = 0;
};

void readOnce(BusExchange &bus, const ServoInfo &servo, bool quiet, std::shared_ptr<Tally> tally,
              SharedIdDone done)
{
    const Block feedback = servo.table().feedbackBlock();
    Exchange ask;
    ask.request = feetech::read(servo.id, quint8(feedback.address), quint8(feedback.size));
    ask.replyId = servo.id;
    ask.replyDataSize = feedback.size;
    ask.retryCount = 0;
    ask.silenceExpected = quiet;
    bus.exchange(ask,
                 [&bus, servo, quiet, tally, done](const seriallink::TransactionResult &result,
                                                   const std::optional<Packet> &reply) {
                     if (result.failure == seriallink::Failure::LinkDown
                         || result.failure == seriallink::Failure::Cancelled) {
                         done(SharedIdVerdict::Failed, result);
                         return;
                     }
                     if (reply)
                         ++tally->clean;
                     else if (result.bytesHeard > 0)
                         ++tally->garbled;
                     else
                         ++tally->silent;
                     if (tally->clean >= kMajority)
                         done(SharedIdVerdict::One, result);
                     else if (tally->garbled >= kMajority)
                         done(SharedIdVerdict::Shared, result);
                     else if (tally->clean + tally->garbled + tally->silent == kSharedIdReads)
                         done(SharedIdVerdict::Silent, result); // it stopped answering
                     else
                         readOnce(bus, servo, quiet, tally, done);
                 });
}

} // namespace

QString sharedIdRefusal(quint8 id)
{
    return SharedIdCheckTr::tr(
               "Two or more servos answer at ID %1 (their replies come back garbled): nothing "
               "is written to it while it is shared. Connect them one at a time and give each "
               "its own ID.")
        .arg(id);
}

void checkSharedId(BusExchange &bus, const ServoInfo &servo, bool quiet, SharedIdDone done)
{
    if (!servo.hasTable()) {
        done(SharedIdVerdict::Unknown, {});
        return;
    }
    readOnce(bus, servo, quiet, std::make_shared<Tally>(), std::move(done));
}

} // namespace feetech
