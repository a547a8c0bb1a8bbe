// The tree of the servos found on the bus: port, baud rates, servos, with their warnings.
#pragma once

#include "bustypes.h"

#include <QTreeWidget>
#include <QVector>

#include <optional>

namespace feetech {
class BusClient;
} // namespace feetech

// A servo is named by its ID and baud rate: the client's numbering changes with every scan.
class ServoTree : public QTreeWidget
{
    Q_OBJECT

public:
    explicit ServoTree(feetech::BusClient *client, QWidget *parent = nullptr);

    void setPortName(const QString &name); // the top item; rebuild() shows it
    // Fills the tree from the client's servos; `current` becomes the current item, and the
    // servos selected before stay selected.
    void rebuild(const std::optional<feetech::ServoAddress> &current);
    // The servos selected (BusClient numbering, tree order); several with Ctrl+click or
    // Shift+click.
    QVector<int> selectedServos() const;

signals:
    // The user chose the servo the pages should show.
    void servoChosen(const feetech::ServoAddress &servo);

private:
    void onSelectionChanged();

    feetech::BusClient *m_client = nullptr;
    QString m_portName;
};
