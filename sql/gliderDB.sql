-- gliderDB.sql: the RIPV vehicle database with GLIDER for VEHICLE, as the thesis did for the
-- Webb Research Slocum glider (section 4.1.4.2). Otherwise identical to vehicleDB.sql.
--
-- Six tables: GLIDER, MISSION, LEG, VEHICLE_DATA, SENSOR, SENSOR_DATA, with the primary
-- keys, foreign keys and NOT NULL constraints of Appendix C. The dialect is the portable
-- core that Apache Derby and PostgreSQL both accept:
--   * VARCHAR for Oracle's VARCHAR2;
--   * TIMESTAMP for Oracle's DATE (an Oracle DATE carries the time of day; a standard DATE
--     does not, and a glider's track needs it);
--   * NOT NULL without a constraint name (Derby cannot name a NOT NULL constraint);
--   * primary and foreign keys keep their Appendix C names (glider_pk, mission_glider_fk, ...).
-- Statements end with ';' at the end of a line. Comments are '--' lines. The RIPV loader
-- (org.ripv.services.database.SqlScript) splits on ';' outside quotes and comments.

CREATE TABLE glider (
    glider_id   INTEGER      CONSTRAINT glider_pk PRIMARY KEY,
    name        VARCHAR(64)  NOT NULL,
    description VARCHAR(256)
);

CREATE TABLE mission (
    mission_id  INTEGER      CONSTRAINT mission_pk PRIMARY KEY,
    glider_id   INTEGER      NOT NULL CONSTRAINT mission_glider_fk REFERENCES glider (glider_id),
    name        VARCHAR(64)  NOT NULL,
    description VARCHAR(256),
    startt      TIMESTAMP,
    endt        TIMESTAMP
);

CREATE TABLE leg (
    leg_id      INTEGER      CONSTRAINT leg_pk PRIMARY KEY,
    mission_id  INTEGER      NOT NULL CONSTRAINT leg_mission_fk REFERENCES mission (mission_id),
    name        VARCHAR(64)  NOT NULL,
    description VARCHAR(256),
    startt      TIMESTAMP,
    endt        TIMESTAMP
);

-- The vehicle's track: position (x east, y north, metres from the mission's origin) and attitude.
CREATE TABLE vehicle_data (
    leg_id      INTEGER          NOT NULL CONSTRAINT vehicle_data_leg_fk REFERENCES leg (leg_id),
    t           TIMESTAMP        NOT NULL,
    x           INTEGER          NOT NULL,
    y           INTEGER          NOT NULL,
    pitch       DOUBLE PRECISION NOT NULL,
    roll        DOUBLE PRECISION NOT NULL
);

CREATE TABLE sensor (
    sensor_id   INTEGER      CONSTRAINT sensor_pk PRIMARY KEY,
    name        VARCHAR(64)  NOT NULL,
    description VARCHAR(256),
    units       VARCHAR(8)   NOT NULL,
    raw_units   VARCHAR(8)   NOT NULL
);

CREATE TABLE sensor_data (
    leg_id      INTEGER          NOT NULL CONSTRAINT sensor_data_leg_fk REFERENCES leg (leg_id),
    sensor_id   INTEGER          NOT NULL CONSTRAINT sensor_data_sensor_fk REFERENCES sensor (sensor_id),
    t           TIMESTAMP        NOT NULL,
    value       DOUBLE PRECISION NOT NULL,
    raw_value   DOUBLE PRECISION NOT NULL
);

-- Not in Appendix C: the queries operators run are "this leg, in time order". Derby indexes
-- foreign keys by itself; PostgreSQL does not, so name the indexes explicitly.
CREATE INDEX vehicle_data_leg_t ON vehicle_data (leg_id, t);
CREATE INDEX sensor_data_leg_sensor_t ON sensor_data (leg_id, sensor_id, t);
