// The guided flows of a Feetech servo: ID change, baud change, middle calibration, reset, reboot.
#pragma once

#include "busexchange.h"
#include "bustypes.h"

#include <QElapsedTimer>
#include <QObject>

#include <functional>
#include <memory>

namespace feetech {

// Each flow checks what it is asked first and writes nothing when that is wrong; once the EEPROM
// may be open it is locked again on every path, wherever the servo ended up. A flow ends by
// calling `finish` once with its result (the servo as it is reached afterwards).
// Lives in the session's thread; the session runs one flow at a time, as an operation.
class GuidedFlows : public QObject
{
    Q_OBJECT

public:
    using Finish = std::function<void(const feetech::OperationResult &result)>;

    explicit GuidedFlows(BusExchange &bus, QObject *parent = nullptr);

    // Refuses an ID in `idsInUse`; follows the servo to its new ID and confirms it there.
    void changeId(const ServoInfo &servo, int newId, const QVector<int> &idsInUse, Finish finish);
    // Refuses a rate where the servo's ID already answers; follows it to the new rate.
    void changeBaud(const ServoInfo &servo, qint32 newBaud, Finish finish);
    // Instruction 0x0B or torque enable 128, by family and firmware.
    void calibrateMiddle(const ServoInfo &servo, Finish finish);
    // Factory values include the baud rate: the servo is looked for at every rate afterwards.
    void factoryReset(const ServoInfo &servo, Finish finish);
    // Torque off, restart, then waits until the servo answers again.
    void reboot(const ServoInfo &servo, Finish finish);

private:
    void waitForReboot(const ServoInfo &servo, std::shared_ptr<QElapsedTimer> clock, Finish finish);

    BusExchange &m_bus;
};

} // namespace feetech
