// The paper's localisation as modes of the whole system. In "laser", the laser-based localiser runs
// on the laser and odometry. When the laser fails, "degraded/odometry" tries to reset it (a laser that
// stays broken cannot be reset, and the mode goes on without it), creates the localiser that uses
// odometry and the gyro (once), and declares the network it needs; the coordinator brings the system
// there and reports done or failed. A laser localiser that fails or exits by itself goes there too. If
// that fails or takes over 10 s, "degraded/safe" stops every localiser. Whenever the laser is active
// again, back to "laser".
modes("localisation") {
    initial("laser")

    mode("laser") {
        network {
            active("laser0.rtc", "laser_localise0.rtc")
            inactive("odo_localise0.rtc")
            connected("laser0.rtc:laser", "laser_localise0.rtc:laser")
            connected("odometry0.rtc:odo", "laser_localise0.rtc:odo")
            disconnected("odometry0.rtc:odo", "odo_localise0.rtc:odo")
            disconnected("gyro0.rtc:gyro", "odo_localise0.rtc:gyro")
        }
        on(component("laser0.rtc")).state(ERROR) goTo "odometry"
        // Exploring found the laser localiser failing or exiting by itself, which left nothing localising.
        on(component("laser_localise0.rtc")).state(ERROR) goTo "odometry"
        on(component("laser_localise0.rtc")).finalized() goTo "odometry"
    }

    mode("degraded") {
        initial("odometry")
        on(component("laser0.rtc")).state(ACTIVE) goTo "laser"

        mode("odometry") {
            entry {
                attempt { component("laser0.rtc").reset(deadline = 1.seconds) }
                try {
                    component("odo_localise0.rtc").state()
                } catch (absent: NotFoundException) {
                    manager().create("odo_localise")
                }
            }
            network {
                inactive("laser_localise0.rtc")
                disconnected("laser0.rtc:laser", "laser_localise0.rtc:laser")
                disconnected("odometry0.rtc:odo", "laser_localise0.rtc:odo")
                connected("odometry0.rtc:odo", "odo_localise0.rtc:odo")
                connected("gyro0.rtc:gyro", "odo_localise0.rtc:gyro")
                active("odo_localise0.rtc")
            }
            initial("switching")
            mode("switching") {
                on(done) goTo "tracking"
                on(failed) goTo "safe"
                after(10.seconds) goTo "safe"
            }
            mode("tracking")
        }

        mode("safe") {
            entry { log("no localiser can run: waiting for the laser") }
            network { inactive("laser_localise0.rtc", "odo_localise0.rtc") }
        }
    }
}
