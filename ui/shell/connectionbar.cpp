// Connection bar: port discovery, settings and the Connect button.
#include "connectionbar.h"

#include "serialportwatcher.h"

#include <QComboBox>
#include <QIntValidator>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTimer>

const QString ConnectionBar::kSimulatedPtkPort =
    QLatin1String(ConnectionController::kSimulatedPtkPort);
const QString ConnectionBar::kSimulatedFeetechPort =
    QLatin1String(ConnectionController::kSimulatedFeetechPort);
const QString ConnectionBar::kSimulatedArmPort =
    QLatin1String(ConnectionController::kSimulatedArmPort);

ConnectionBar::ConnectionBar(QWidget *parent)
    : QToolBar(tr("Connection"), parent)
{
    setObjectName(QStringLiteral("connectionBar"));
    setMovable(false);

    addWidget(new QLabel(tr("Port "), this));
    m_port = new QComboBox(this);
    m_port->setObjectName(QStringLiteral("portCombo"));
    m_port->setEditable(true); // a path the list does not show, e.g. servosim's link
    m_port->setInsertPolicy(QComboBox::NoInsert);
    m_port->setMinimumContentsLength(24);
    m_port->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_port->setToolTip(tr("The serial port of the USB programmer, or a simulated servo"));
    m_port->lineEdit()->setPlaceholderText(tr("Choose a port"));
    addWidget(m_port);
    connect(m_port, &QComboBox::activated, this, [this] {
        m_portChosen = true;
        if (const auto spoken = ConnectionController::simulatedProtocol(port()))
            setProtocol(*spoken);
    });
    connect(m_port->lineEdit(), &QLineEdit::textEdited, this, [this] { m_portChosen = true; });
    connect(m_port, &QComboBox::currentTextChanged, this, &ConnectionBar::onPortEdited);

    addSeparator();
    addWidget(new QLabel(tr("Baud "), this));
    m_baud = new QComboBox(this);
    m_baud->setObjectName(QStringLiteral("baudCombo"));
    m_baud->setEditable(true);
    m_baud->setValidator(new QIntValidator(1200, 4000000, m_baud));
    for (const int rate : {115200, 57600, 38400, 19200, 9600, 1000000, 500000, 250000, 128000})
        m_baud->addItem(QString::number(rate));
    m_baud->setToolTip(tr("PTK servos talk at 115200 baud. On a Feetech bus this is the rate "
                          "the port opens at; a scan visits the rates it is asked to."));
    addWidget(m_baud);

    addSeparator();
    addWidget(new QLabel(tr("Protocol "), this));
    m_protocol = new QComboBox(this);
    m_protocol->setObjectName(QStringLiteral("protocolCombo"));
    m_protocol->addItem(tr("Auto"), int(Protocol::Auto));
    m_protocol->addItem(tr("PTK RC servo"), int(Protocol::Ptk));
    m_protocol->addItem(tr("Feetech bus"), int(Protocol::Feetech));
    m_protocol->setToolTip(tr("Auto: ServoBench asks the port who is there (it only asks, it "
                              "writes nothing) and opens the right workspace at the right "
                              "rate. PTK: one RC servo on a USB programmer. Feetech: SCS, STS, "
                              "SMS and HLS servos on a serial bus."));
    addWidget(m_protocol);
    connect(m_protocol, &QComboBox::currentIndexChanged, this, [this] {
        if (protocol() != Protocol::Auto) {
            const QString rate =
                protocol() == Protocol::Ptk ? QStringLiteral("115200") : QStringLiteral("1000000");
            m_baud->setCurrentIndex(m_baud->findText(rate));
        }
        updateEnabled();
        emit protocolChanged(protocol());
    });

    addSeparator();
    addWidget(new QLabel(tr("Echo "), this));
    m_echo = new QComboBox(this);
    m_echo->setObjectName(QStringLiteral("echoCombo"));
    m_echo->addItem(tr("Auto"), int(seriallink::EchoMode::Auto));
    m_echo->addItem(tr("On"), int(seriallink::EchoMode::On));
    m_echo->addItem(tr("Off"), int(seriallink::EchoMode::Off));
    m_echo->setToolTip(tr("Single-wire programmers send every byte back. Auto detects it."));
    addWidget(m_echo);

    addSeparator();
    m_connect = new QPushButton(tr("Connect"), this);
    m_connect->setObjectName(QStringLiteral("connectButton"));
    m_connect->setDefault(true);
    addWidget(m_connect);
    connect(m_connect, &QPushButton::clicked, this, [this] {
        if (m_active)
            emit disconnectRequested();
        else
            emit connectRequested();
    });

    // Asking the system for its ports can take a while: the window shows first, with the
    // simulated buses, and the real ports join the list once the event loop runs. From then on
    // the list follows adapters plugged in and pulled out.
    showPorts({});
    QTimer::singleShot(0, this, [this] {
        SerialPortWatcher &watcher = SerialPortWatcher::shared();
        connect(&watcher, &SerialPortWatcher::portsChanged, this, &ConnectionBar::takePorts);
        takePorts(watcher.ports());
    });
    updateEnabled();
}

void ConnectionBar::onPortEdited()
{
    const QString chosen = port();
    updateEnabled();
    if (chosen == m_lastPort)
        return;
    m_lastPort = chosen;
    emit portChanged(chosen);
}

QString ConnectionBar::port() const
{
    const int index = m_port->findText(m_port->currentText());
    if (index >= 0 && !m_port->itemData(index).toString().isEmpty())
        return m_port->itemData(index).toString();
    return m_port->currentText().trimmed();
}

void ConnectionBar::setPort(const QString &port)
{
    m_portChosen = true;
    selectPort(port);
}

void ConnectionBar::selectPort(const QString &port)
{
    const int index = m_port->findData(port);
    if (index >= 0)
        m_port->setCurrentIndex(index);
    else
        m_port->setEditText(port);
}

qint32 ConnectionBar::baud() const
{
    return m_baud->currentText().toInt();
}

ConnectionBar::Protocol ConnectionBar::protocol() const
{
    return Protocol(m_protocol->currentData().toInt());
}

void ConnectionBar::setProtocol(Protocol protocol)
{
    m_protocol->setCurrentIndex(m_protocol->findData(int(protocol)));
}

seriallink::EchoMode ConnectionBar::echoMode() const
{
    return seriallink::EchoMode(m_echo->currentData().toInt());
}

void ConnectionBar::setBaud(qint32 baud)
{
    const QString rate = QString::number(baud);
    if (m_baud->findText(rate) >= 0)
        m_baud->setCurrentIndex(m_baud->findText(rate));
    else
        m_baud->setEditText(rate);
}

void ConnectionBar::showDetected(qint32 baud, seriallink::EchoMode echo)
{
    setBaud(baud);
    m_echo->setCurrentIndex(m_echo->findData(int(echo)));
}

void ConnectionBar::setSessionActive(bool active)
{
    m_active = active;
    m_connect->setText(active ? tr("Disconnect") : tr("Connect"));
    updateEnabled();
}

void ConnectionBar::updateEnabled()
{
    const bool chosenByHand = protocol() != Protocol::Auto;
    m_port->setEnabled(!m_active);
    m_protocol->setEnabled(!m_active);
    m_baud->setEnabled(!m_active && chosenByHand);
    m_echo->setEnabled(!m_active && chosenByHand);
    m_connect->setEnabled(m_active || canConnect());
    m_connect->setToolTip(m_active || canConnect() ? QString()
                                                   : tr("Choose a serial port or a simulated "
                                                        "servo first"));
}

void ConnectionBar::refreshPorts()
{
    SerialPortWatcher::shared().rescan();
    takePorts(SerialPortWatcher::shared().ports());
}

void ConnectionBar::takePorts(const QVector<SerialPort> &ports)
{
    const bool same = ports == m_knownPorts && m_port->count() > 0;
    m_portsListed = true;
    if (!same)
        showPorts(ports);
}

void ConnectionBar::showPorts(const QVector<SerialPort> &ports)
{
    m_knownPorts = ports;
    // Rebuilding the list must not lose what the user chose or is typing. Until the user
    // chooses, the first USB adapter is the choice (none before the system's ports are known).
    QString chosen = m_portChosen ? port() : QString();
    if (!m_portChosen && m_portsListed && !ports.isEmpty())
        chosen = ports.first().path;
    {
        const QSignalBlocker quiet(m_port);
        m_port->clear();
        for (const SerialPort &system : ports) {
            const QString text = system.description.isEmpty()
                ? system.path
                : QStringLiteral("%1 (%2)").arg(system.path, system.description);
            m_port->addItem(text, system.path);
        }
        m_port->addItem(tr("Simulated PTK servo"), kSimulatedPtkPort);
        m_port->addItem(tr("Simulated Feetech bus"), kSimulatedFeetechPort);
        m_port->addItem(tr("Simulated SO-101 arm"), kSimulatedArmPort);
        if (chosen.isEmpty()) {
            m_port->setCurrentIndex(-1);
            m_port->setEditText(QString());
        } else {
            selectPort(chosen);
        }
    }
    onPortEdited();
}
