//! The parts of the `shenlong` command that are worth testing from outside: the web
//! editor's server.

pub mod server;
