// Looking for the one servo on the bus: a broadcast PING at every baud rate, then the servo
// found identified, checked for a second one at its ID, and its model judged.
#pragma once

#include "busexchange.h"
#include "bustypes.h"
#include "motorsearch.h"

#include <QString>
#include <QStringList>
#include <QStringView>
#include <QVector>

#include <functional>
#include <memory>

namespace feetech {

// Whether the servo is of the model the model table names `model` (aliases included).
bool servoIsModel(const ServoInfo &servo, QStringView model);

// Lives in the session's thread, as the set-up that uses it; reads, never writes.
class MotorFinder
{
public:
    using SearchDone = std::function<void(const MotorSearch &search)>;

    // `stopRequested` is asked before each rate: true ends the search as stopped.
    MotorFinder(BusExchange &bus, std::function<bool()> stopRequested);

    // A READ of addresses 0-8 of `id`; a quiet one is no error when nothing answers.
    static Exchange identityRequest(quint8 id, bool quiet);

    // A broadcast PING at every rate, then the one servo's identity and a few reads of its
    // feedback (two servos at one ID garble those), then its model against `model` (empty: any
    // model with a register table). `joint` names the motor in messages; may be empty.
    void find(const QString &model, const QString &joint, SearchDone done);

private:
    struct Search;
    void probeRate(std::shared_ptr<Search> search, int index);
    void decide(std::shared_ptr<Search> search);
    void confirm(std::shared_ptr<Search> search, quint8 id, qint32 baud);
    // Whether two servos share the one ID found (sharedidcheck.h), then its model.
    void checkShared(std::shared_ptr<Search> search);
    void judgeModel(std::shared_ptr<Search> search);
    void endSearch(std::shared_ptr<Search> search, MotorSearch::Verdict verdict,
                   const QString &message);

    BusExchange &m_bus;
    std::function<bool()> m_stopRequested;
};

} // namespace feetech
