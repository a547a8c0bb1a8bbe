// A search's verdict as the kind of an operation's failure.
#include "motorsearch.h"

namespace feetech {

OperationFailure MotorSearch::failure() const
{
    switch (verdict) {
    case Verdict::NoServo:
        return OperationFailure::NoAnswer;
    case Verdict::OneServo:
        return OperationFailure::None;
    case Verdict::SeveralServos:
        return OperationFailure::SeveralServos;
    case Verdict::SharedId:
        return OperationFailure::SharedId;
    case Verdict::WrongModel:
        return OperationFailure::WrongModel;
    case Verdict::Failed:
        return stopped ? OperationFailure::Stopped : OperationFailure::LinkLost;
    }
    return OperationFailure::None;
}

} // namespace feetech
