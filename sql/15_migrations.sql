-- Brings a database created by an earlier fleetmap up to the current schema.
-- Idempotent: every step is ADD ... IF NOT EXISTS (10_schema.sql already has them all
-- for a new database, so on a new database nothing here changes anything).

-- server issue: sessions, pushed aborts, georeferenced maps
ALTER TABLE robots ADD COLUMN IF NOT EXISTS session_at TIMESTAMP(6) NULL AFTER magic;
ALTER TABLE tasks ADD COLUMN IF NOT EXISTS abort_requested_at TIMESTAMP(6) NULL AFTER answer_id;
ALTER TABLE tasks ADD COLUMN IF NOT EXISTS abort_answer_id BIGINT UNSIGNED NULL AFTER abort_requested_at;
ALTER TABLE maps ADD COLUMN IF NOT EXISTS geo_lat DOUBLE NULL AFTER imported_at;
ALTER TABLE maps ADD COLUMN IF NOT EXISTS geo_lon DOUBLE NULL AFTER geo_lat;
ALTER TABLE maps ADD COLUMN IF NOT EXISTS geo_heading DOUBLE NULL AFTER geo_lon;

-- semantic layer (issue 8): robot profiles
ALTER TABLE robots ADD COLUMN IF NOT EXISTS laser_height DOUBLE NULL AFTER removed_at;
ALTER TABLE robots ADD COLUMN IF NOT EXISTS radius DOUBLE NULL AFTER laser_height;
ALTER TABLE robots ADD COLUMN IF NOT EXISTS body_height DOUBLE NULL AFTER radius;
ALTER TABLE robots ADD COLUMN IF NOT EXISTS can_stairs BOOLEAN NOT NULL DEFAULT FALSE AFTER body_height;
ALTER TABLE robots ADD COLUMN IF NOT EXISTS can_ramps BOOLEAN NOT NULL DEFAULT TRUE AFTER can_stairs;
