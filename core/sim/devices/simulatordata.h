// The simulator's per-family facts that no register table holds: the firmware each simulated
// family reports and the factory values used where a table leaves a default open.
#pragma once

#include "registertable.h"

#include <QByteArray>
#include <QHash>
#include <QString>
#include <QStringView>

#include <array>
#include <iterator>
#include <optional>

namespace sim {

struct SimulatedFirmware
{
    int major = 0;
    int minor = 0;
};

class SimulatorData
{
public:
    // resources/feetech/simulator.json, compiled in; a malformed built-in file stops the program
    // with the message parse() gives.
    static const SimulatorData &builtIn();

    // The file's data, or nothing and *error naming `fileName` and the field that is wrong.
    static std::optional<SimulatorData> parse(const QByteArray &json, const QString &fileName,
                                              QString *error);

    SimulatedFirmware firmware(feetech::Family family) const;
    // The value a fresh simulated servo gets for `key` when its table gives no default, so it
    // is neither in alarm (max temperature 0) nor powerless (max torque 0).
    std::optional<qint32> fallbackDefault(feetech::Family family, QStringView key) const;

private:
    struct FamilyData
    {
        SimulatedFirmware firmware;
        QHash<QString, qint32> defaults; // the file's common defaults with the family's own
    };

    static std::size_t index(feetech::Family family);

    std::array<FamilyData, std::size(feetech::kAllFamilies)> m_families;
};

} // namespace sim
