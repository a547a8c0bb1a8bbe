// What a look for the one servo on the bus found: a verdict, the servo, what to tell the user.
#pragma once

#include "bustypes.h"

#include <QString>
#include <QStringList>

namespace feetech {

// What a look at every baud rate found.
struct MotorSearch
{
    enum class Verdict {
        NoServo, // nothing answers at any rate (or the one servo stopped answering)
        OneServo, // exactly one servo, of the right model: `servo`
        SeveralServos, // answers at several rates, from several IDs, or replies that collide
        SharedId, // two servos at one ID: clean PING and identity, garbled position reads
        WrongModel, // one servo, of another model (or one without a register table)
        Failed // the port closed, or the search was stopped
    };
    Verdict verdict = Verdict::NoServo;
    ServoInfo servo; // OneServo, WrongModel, SharedId: who answers
    int count = 0; // servos seen; with `collided`, at least that many
    bool collided = false; // some replies collided, so more may answer than could be counted
    bool stopped = false; // cancelled before it could decide
    QStringList answering; // SeveralServos: "ID 1 at 1 Mbps", "several at 500 kbps"...
    QString message; // for the user: what was found and what to do

    bool foundOne() const { return verdict == Verdict::OneServo; }
    // The verdict as the kind of the operation's failure (None when it found one servo).
    OperationFailure failure() const;
    // The bus is not as a set-up needs it, and the message does not say so itself.
    bool needsNothingWrittenNote() const
    {
        return verdict == Verdict::NoServo || verdict == Verdict::SeveralServos
            || verdict == Verdict::SharedId;
    }
};

} // namespace feetech
