// Whether two servos answer at one ID: alike in their identity, apart in their feedback.
#pragma once

#include "busexchange.h"

namespace feetech {

// Two servos at one ID answer each request in the same instant. Their identities (model,
// firmware) are the same bytes and pass unharmed; their present position, load and current
// differ, and replies to a read of the feedback block garble where they do. A majority of a few
// such reads decides.
enum class SharedIdVerdict {
    One, // the reads came back clean
    Shared, // most reads came back garbled
    Silent, // no majority: reads went unanswered
    Unknown, // the servo has no known table: nothing to read
    Failed // the link was lost or the operation cancelled (see the result)
};

using SharedIdDone =
    std::function<void(SharedIdVerdict verdict, const seriallink::TransactionResult &last)>;

// Reads `servo`'s feedback block until a majority of kSharedIdReads agrees. `quiet`: the reads
// are a scan's, whose silences and garbled answers are no link errors.
void checkSharedId(BusExchange &bus, const ServoInfo &servo, bool quiet, SharedIdDone done);

constexpr int kSharedIdReads = 3;

// Why nothing is written to an ID several servos answer at, and what to do.
QString sharedIdRefusal(quint8 id);

} // namespace feetech
