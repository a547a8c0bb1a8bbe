// The health check's reads of one servo: its limits, then the feedback block again and again,
// counting what the link had to do to get each answer. Reads only, never a write.
#pragma once

#include "busexchange.h"
#include "servohealth.h"

#include <QObject>

#include <functional>
#include <memory>

namespace feetech {

// Lives in the session's thread; the session runs it once per servo of a check.
class HealthCheck : public QObject
{
    Q_OBJECT

public:
    explicit HealthCheck(BusExchange &bus, QObject *parent = nullptr);

    // Reads the registers the verdict compares against (firmware, model, angle, voltage and
    // temperature limits, overload level), then `reads` feedback blocks one after the other.
    // A read that fails is counted, not fatal: `done` always gets the reading.
    void read(const ServoInfo &servo, int reads, std::function<void(const HealthReading &)> done);

    // Stops a check between two servos (see Session::checkHealth).
    void cancel() { m_cancelled = true; }
    void clearCancel() { m_cancelled = false; }
    bool isCancelled() const { return m_cancelled; }

private:
    struct Run;
    void readLimits(std::shared_ptr<Run> run);
    void readFeedback(std::shared_ptr<Run> run);

    BusExchange &m_bus;
    bool m_cancelled = false;
};

} // namespace feetech
