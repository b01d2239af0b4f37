//! The parts of the `shenlong` command that are worth testing from outside: the web
//! editor's server, and the editing session it shares with the MCP server.

pub mod server;
pub mod session;
