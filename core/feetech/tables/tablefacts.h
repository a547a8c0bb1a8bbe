// Protocol facts a register table states beside its registers: torque values, feedback block.
#pragma once

#include <QJsonObject>
#include <QString>
#include <QVector>

#include <array>
#include <optional>

namespace feetech {

struct Register;

// What writing the torque-enable register means (spec §5): the values differ by family, and
// not every family has damping or the calibrate-middle value.
enum class TorqueMode { Off, On, Damping, CalibrateMiddle };

struct TableFacts
{
    std::array<std::optional<qint32>, 4> torqueValues; // by TorqueMode
    int feedbackAddress = 0; // present position through present current, read in one go
    int feedbackSize = 0;
};

// Reads "torque_enable_values" and "feedback_block" of a register file and checks them against
// its registers (each torque value one of torque_enable's choices, the block within the table).
// Each is required when the table has the register it speaks of (torque_enable,
// present_position). Nothing, and *error naming the field, when one is missing or wrong.
std::optional<TableFacts> parseTableFacts(const QJsonObject &root,
                                          const QVector<Register> &registers, QString *error);

// Reads "baud_rates" of the model table: the rate of each baud code, code 0 first.
std::optional<QVector<qint32>> parseBaudRates(const QJsonObject &root, QString *error);

} // namespace feetech
