// Fuzz target: bytes a program and a bus exchange through a share, as the share reads them:
// framed, paired into transactions, learned into each servo's memory, checked for alerts. The
// input is a run of chunks, each a length byte whose top bit says the side, then its bytes.
#include "feetechpacket.h"
#include "fuzztarget.h"
#include "observedservos.h"
#include "sharealerts.h"
#include "streamframer.h"
#include "transactiontracker.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray input = fuzz::input(data, size);
    share::ObservedServos servos;
    share::ShareAlerts alerts;
    int transactions = 0;
    share::TransactionTracker tracker([&](share::SharedTransaction &&transaction) {
        ++transactions;
        servos.learn(transaction, 1000000);
        for (const share::RegisterAccess &access : transaction.registers)
            FUZZ_CHECK(servos.table(access.id) != nullptr);
        for (const share::ShareAlert &alert : alerts.inspect(transaction, servos))
            FUZZ_CHECK(!alert.code.isEmpty() && !alert.message.isEmpty());
        FUZZ_CHECK(!transaction.toJson().isEmpty());
    });
    const feetech::FrameFormat format;
    seriallink::StreamFramer program(format,
                                     seriallink::StreamFramer::BadChecksumPolicy::ConsumeFrame);
    seriallink::StreamFramer bus(format, seriallink::StreamFramer::BadChecksumPolicy::ConsumeFrame);
    qint64 now = 0;
    int requests = 0;
    for (qsizetype at = 0; at < input.size();) {
        const quint8 head = quint8(input.at(at++));
        const bool fromProgram = head & 0x80;
        const QByteArray chunk = input.mid(at, head & 0x7F);
        at += chunk.size();
        now += 100;
        seriallink::StreamFramer &framer = fromProgram ? program : bus;
        framer.append(chunk);
        while (const auto item = framer.next()) {
            if (!fromProgram)
                tracker.heard(*item, now);
            else if (item->kind == seriallink::StreamItem::Kind::Frame) {
                tracker.request(item->bytes, now);
                ++requests;
            }
        }
        tracker.expire(now);
        alerts.tick(now);
    }
    tracker.expire(now + (qint64(1) << 40));
    FUZZ_CHECK(!tracker.isOutstanding());
    FUZZ_CHECK(transactions == requests);
    return 0;
}
