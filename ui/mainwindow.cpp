// ServoBench's main window.
#include "mainwindow.h"

#include <QAction>
#include <QApplication>
#include <QKeySequence>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QVBoxLayout>

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent)
{
    setWindowTitle(tr("ServoBench"));
    setObjectName(QStringLiteral("mainWindow"));
    resize(1100, 720);

    auto *welcome = new QLabel(this);
    welcome->setObjectName(QStringLiteral("welcome"));
    welcome->setAlignment(Qt::AlignCenter);
    welcome->setWordWrap(true);
    welcome->setTextFormat(Qt::RichText);
    welcome->setText(tr("<h2>ServoBench</h2>"
                        "<p>Programmer and live monitor for PTK RC servos and Feetech "
                        "SCS / SMS / STS / HLS serial-bus servos.</p>"));
    welcome->setContentsMargins(24, 24, 24, 24);
    setCentralWidget(welcome);

    createMenus();
    m_connectionState = new QLabel(tr("Not connected"), this);
    m_connectionState->setObjectName(QStringLiteral("connectionState"));
    statusBar()->addWidget(m_connectionState);
}

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QAction *quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    quit->setObjectName(QStringLiteral("quitAction"));

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    QAction *about = help->addAction(tr("&About ServoBench"), this, &MainWindow::showAbout);
    about->setObjectName(QStringLiteral("aboutAction"));
    help->addAction(tr("About &Qt"), qApp, &QApplication::aboutQt);
}

void MainWindow::showAbout()
{
    QMessageBox::about(this, tr("About ServoBench"),
                       tr("<p><b>ServoBench %1</b></p>"
                          "<p>Programs and monitors PTK RC servos and Feetech serial-bus "
                          "servos on Linux, Windows and macOS.</p>")
                           .arg(QCoreApplication::applicationVersion()));
}
