//! Test support shared by the integration tests.

pub mod mock_llm;
pub mod shared_data;
