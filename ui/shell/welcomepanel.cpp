// The page shown while nothing is connected: the serial ports with their USB descriptions, the
// simulated servos, and how to wire each servo family.
#include "welcomepanel.h"

#include "connectionbar.h"

#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSerialPortInfo>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace {

constexpr int kRefreshMs = 2000;

enum PortColumnIndex {
    PortColumn,
    DescriptionColumn,
    ManufacturerColumn,
    SerialColumn,
    UsbIdColumn
};

QString usbId(const QSerialPortInfo &info)
{
    if (!info.hasVendorIdentifier() || !info.hasProductIdentifier())
        return {};
    return QStringLiteral("%1:%2")
        .arg(info.vendorIdentifier(), 4, 16, QLatin1Char('0'))
        .arg(info.productIdentifier(), 4, 16, QLatin1Char('0'));
}

QLabel *wrappedLabel(const QString &text, QWidget *parent)
{
    auto *label = new QLabel(text, parent);
    label->setWordWrap(true);
    label->setTextFormat(Qt::RichText);
    return label;
}

} // namespace

WelcomePanel::WelcomePanel(QWidget *parent)
    : QWidget(parent)
    , m_refresh(new QTimer(this))
{
    setObjectName(QStringLiteral("welcomePanel"));
    auto *title = new QLabel(tr("<h2>Connect your servos</h2>"), this);
    auto *intro =
        wrappedLabel(tr("Choose the serial port of your USB adapter and press "
                        "<b>Connect</b> (or double-click it), or try ServoBench on "
                        "simulated servos. Nothing is sent to a servo until you connect."),
                     this);
    auto *columns = new QHBoxLayout;
    auto *left = new QVBoxLayout;
    left->addWidget(createPortsBox(), 1);
    left->addWidget(createSimulatedBox());
    columns->addLayout(left, 3);
    columns->addWidget(createWiringBox(), 2);

    auto *layout = new QVBoxLayout(this);
    layout->addWidget(title);
    layout->addWidget(intro);
    layout->addLayout(columns, 1);

    m_refresh->setInterval(kRefreshMs);
    connect(m_refresh, &QTimer::timeout, this, &WelcomePanel::refreshPorts);
    refreshPorts();
}

QWidget *WelcomePanel::createPortsBox()
{
    auto *box = new QGroupBox(tr("Serial ports"), this);
    m_ports = new QTableWidget(0, 5, box);
    m_ports->setObjectName(QStringLiteral("welcomePorts"));
    m_ports->setHorizontalHeaderLabels(
        {tr("Port"), tr("Description"), tr("Manufacturer"), tr("Serial number"), tr("USB ID")});
    m_ports->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_ports->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_ports->setSelectionMode(QAbstractItemView::SingleSelection);
    m_ports->verticalHeader()->hide();
    m_ports->horizontalHeader()->setStretchLastSection(true);
    connect(m_ports, &QTableWidget::itemSelectionChanged, this,
            [this] { m_connect->setEnabled(!m_ports->selectedItems().isEmpty()); });
    connect(m_ports, &QTableWidget::itemDoubleClicked, this, &WelcomePanel::connectSelected);
    m_noPorts = new QLabel(tr("No serial port found. Plug in the USB adapter: it shows up here "
                              "by itself."),
                           box);
    m_noPorts->setObjectName(QStringLiteral("noPortsLabel"));
    m_noPorts->setWordWrap(true);
    m_connect = new QPushButton(tr("Connect"), box);
    m_connect->setObjectName(QStringLiteral("welcomeConnectButton"));
    m_connect->setEnabled(false);
    connect(m_connect, &QPushButton::clicked, this, &WelcomePanel::connectSelected);

    auto *layout = new QVBoxLayout(box);
    layout->addWidget(m_ports, 1);
    layout->addWidget(m_noPorts);
    auto *buttons = new QHBoxLayout;
    buttons->addStretch();
    buttons->addWidget(m_connect);
    layout->addLayout(buttons);
    return box;
}

QWidget *WelcomePanel::createSimulatedBox()
{
    auto *box = new QGroupBox(tr("Simulated servos"), this);
    auto *layout = new QHBoxLayout(box);
    const struct
    {
        QString text;
        QString port;
        const char *name;
    } buses[] = {
        {tr("PTK servo"), ConnectionBar::kSimulatedPtkPort, "simulatedPtkButton"},
        {tr("Feetech bus (five servos)"), ConnectionBar::kSimulatedFeetechPort,
         "simulatedFeetechButton"},
        {tr("SO-101 arm (six STS3215)"), ConnectionBar::kSimulatedArmPort, "simulatedArmButton"},
    };
    for (const auto &bus : buses) {
        auto *button = new QPushButton(bus.text, box);
        button->setObjectName(QLatin1String(bus.name));
        connect(button, &QPushButton::clicked, this,
                [this, port = bus.port] { emit connectRequested(port); });
        layout->addWidget(button);
    }
    layout->addStretch();
    return box;
}

QWidget *WelcomePanel::createWiringBox()
{
    auto *box = new QGroupBox(tr("Wiring"), this);
    auto *layout = new QVBoxLayout(box);
    layout->addWidget(wrappedLabel(
        tr("<b>PTK RC servos</b> (one signal wire, 115200 baud): a 3.3 V or 5 V USB-serial "
           "adapter with a 470 Ω resistor from TX to RX. The servo's signal wire goes to RX, "
           "its ground to the adapter's ground; power the servo from its own supply. The "
           "adapter hears its own bytes, and ServoBench expects that."),
        box));
    layout->addWidget(wrappedLabel(
        tr("<b>Feetech serial-bus servos</b>: Feetech's URT-1 / FE-URT board, or any "
           "half-duplex TTL adapter (SCS, STS, HLS) or RS485 adapter (SMS). Chain the servos "
           "with their 3-wire cables; power them from the board's supply (7.4 V or 12 V as "
           "the servos ask), never from USB. New servos all answer at ID 1 and 1 Mbps: set "
           "them up one at a time (Robot > Set up motors)."),
        box));
    layout->addWidget(wrappedLabel(
        tr("Nothing answers? Leave Protocol on <b>Auto</b> and connect: ServoBench finds the "
           "family and rate, and the Doctor says what is wrong."),
        box));
    layout->addStretch();
    return box;
}

void WelcomePanel::refreshPorts()
{
    const QString selected = m_ports->selectedItems().isEmpty()
        ? QString()
        : m_ports->item(m_ports->currentRow(), PortColumn)->data(Qt::UserRole).toString();
    const QList<QSerialPortInfo> ports = QSerialPortInfo::availablePorts();
    // Rebuilt only when the list changed, so the view neither flickers nor scrolls.
    QStringList listed;
    for (const QSerialPortInfo &info : ports)
        listed.append(info.systemLocation() + u'|' + info.description() + u'|'
                      + info.serialNumber());
    if (listed == m_listed && m_ports->rowCount() == ports.size())
        return;
    m_listed = listed;
    m_ports->setRowCount(0);
    for (const QSerialPortInfo &info : ports) {
        const int row = m_ports->rowCount();
        m_ports->insertRow(row);
        auto *port = new QTableWidgetItem(info.portName());
        port->setData(Qt::UserRole, info.systemLocation());
        port->setToolTip(info.systemLocation());
        m_ports->setItem(row, PortColumn, port);
        m_ports->setItem(row, DescriptionColumn, new QTableWidgetItem(info.description()));
        m_ports->setItem(row, ManufacturerColumn, new QTableWidgetItem(info.manufacturer()));
        m_ports->setItem(row, SerialColumn, new QTableWidgetItem(info.serialNumber()));
        m_ports->setItem(row, UsbIdColumn, new QTableWidgetItem(usbId(info)));
        if (info.systemLocation() == selected)
            m_ports->selectRow(row);
    }
    m_ports->resizeColumnsToContents();
    m_noPorts->setVisible(ports.isEmpty());
    m_connect->setEnabled(!m_ports->selectedItems().isEmpty());
}

void WelcomePanel::connectSelected()
{
    if (m_ports->selectedItems().isEmpty())
        return;
    emit connectRequested(
        m_ports->item(m_ports->currentRow(), PortColumn)->data(Qt::UserRole).toString());
}

void WelcomePanel::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    refreshPorts();
    m_refresh->start();
}

void WelcomePanel::hideEvent(QHideEvent *event)
{
    QWidget::hideEvent(event);
    m_refresh->stop();
}
